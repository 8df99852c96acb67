#include "ui/tables/editable_table_model.h"

namespace kerf::ui {

int EditableTableModel::findRow(const QString& text, int from) const {
    const int rows = rowCount();
    for (int i = 0; i < rows; ++i) {
        const int row = (from + i) % rows;
        for (int column = 0; column < columnCount(); ++column) {
            if (data(index(row, column), Qt::DisplayRole)
                    .toString()
                    .contains(text, Qt::CaseInsensitive)) {
                return row;
            }
        }
    }
    return -1;
}

}  // namespace kerf::ui
