#include "ui/tables/tnc_table_model.h"

#include <QBrush>
#include <QColor>
#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "core/tables/table_file.h"
#include "core/tables/table_validation.h"

namespace kerf::ui {

namespace {

constexpr size_t kMaxUndo = 200;

bool isIn(std::string_view name, std::initializer_list<std::string_view> names) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

TncTableModel::TncTableModel(tables::TncTable table, QObject* parent, Validator validator)
    : EditableTableModel(parent), m_table(std::move(table)), m_validator(std::move(validator)) {}

int TncTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_table.rowCount());
}

int TncTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_table.columns().size());
}

QVariant TncTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    const auto row = static_cast<size_t>(index.row());
    const auto column = static_cast<size_t>(index.column());
    if (role == Qt::DisplayRole || role == Qt::EditRole) {
        const std::string_view cell = m_table.cell(row, column);
        return QString::fromUtf8(cell.data(), static_cast<int>(cell.size()));
    }
    if (role == Qt::TextAlignmentRole && m_table.columnFormat(column).numeric()) {
        return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    }
    return {};
}

QVariant TncTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole) return {};
    if (orientation == Qt::Vertical) return section + 1;
    const auto column = static_cast<size_t>(section);
    if (column >= m_table.columns().size()) return {};
    const QString name = QString::fromStdString(m_table.columns()[column].name);
    const QString unit = columnUnit(column);
    return unit.isEmpty() ? name : QStringLiteral("%1\n[%2]").arg(name, unit);
}

Qt::ItemFlags TncTableModel::flags(const QModelIndex& index) const {
    return EditableTableModel::flags(index) | Qt::ItemIsEditable;
}

bool TncTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || role != Qt::EditRole) return false;
    const auto row = static_cast<size_t>(index.row());
    const auto column = static_cast<size_t>(index.column());
    const std::string text = value.toString().trimmed().toStdString();
    if (text == m_table.cell(row, column)) return false;
    tables::TncTable before = m_table;
    if (const MaybeError error = m_table.setCell(row, column, text)) {
        emit refused(*error);
        return false;
    }
    m_undo.push_back(std::move(before));
    if (m_undo.size() > kMaxUndo) m_undo.erase(m_undo.begin());
    m_modified = true;
    emit dataChanged(index, index);
    return true;
}

void TncTableModel::remember() {
    m_undo.push_back(m_table);
    if (m_undo.size() > kMaxUndo) m_undo.erase(m_undo.begin());
}

int TncTableModel::insertKeyedRow(int row) {
    row = std::clamp(row, 0, rowCount());
    double largest = -1;
    for (size_t r = 0; r < m_table.rowCount(); ++r) {
        if (auto key = m_table.number(r, 0)) largest = std::max(largest, std::floor(*key));
    }
    const std::string key = std::to_string(static_cast<long long>(largest + 1));
    tables::TncTable before = m_table;
    beginInsertRows({}, row, row);
    auto inserted = m_table.insertRow(static_cast<size_t>(row), key);
    endInsertRows();
    if (!inserted) {
        beginResetModel();
        m_table = std::move(before);
        endResetModel();
        emit refused(inserted.error());
        return -1;
    }
    m_undo.push_back(std::move(before));
    m_modified = true;
    return row;
}

bool TncTableModel::removeTableRow(int row) {
    if (row < 0 || row >= rowCount()) return false;
    remember();
    beginRemoveRows({}, row, row);
    const MaybeError error = m_table.removeRow(static_cast<size_t>(row));
    endRemoveRows();
    if (error) {
        undo();
        emit refused(*error);
        return false;
    }
    m_modified = true;
    return true;
}

void TncTableModel::undo() {
    if (m_undo.empty()) return;
    beginResetModel();
    m_table = std::move(m_undo.back());
    m_undo.pop_back();
    endResetModel();
    m_modified = true;
}

QString TncTableModel::columnUnit(size_t column) const {
    const std::string& name = m_table.columns().at(column).name;
    if (isIn(name, {"L",      "R",       "R2",      "DL",   "DR",    "DR2",      "LCUTS",  "PITCH",
                    "X",      "Y",       "Z",       "U",    "V",     "W",        "R-OFFS", "L-OFFS",
                    "LBREAK", "RBREAK",  "LTOL",    "RTOL", "R2TOL", "DIAMETER", "ZL",     "XL",
                    "YL",     "CAL_OF1", "CAL_OF2", "DIST", "SET_UP"})) {
        return m_table.unit() == "INCH" ? QStringLiteral("inch") : QStringLiteral("mm");
    }
    if (isIn(name, {"ANGLE", "T-ANGLE", "A", "B", "C", "ROT", "CAL_ANG"}))
        return QStringLiteral("\u00b0");
    if (isIn(name, {"TIME1", "TIME2", "CUR_TIME", "CUR.TIME"})) return QStringLiteral("min");
    // Only the touch-probe table has feed columns; elsewhere F may mean something else.
    if (m_table.extension() == "TP" && isIn(name, {"F", "FMAX"})) {
        return m_table.unit() == "INCH" ? QStringLiteral("inch/min") : QStringLiteral("mm/min");
    }
    return {};
}

DiagnosticList TncTableModel::validate() const {
    return m_validator ? m_validator(m_table) : tables::checkNumericCells(m_table);
}

std::string TncTableModel::content() const {
    return m_table.serialize();
}

}  // namespace kerf::ui
