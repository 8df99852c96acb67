#pragma once

#include <functional>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/tables/tnc_table.h"
#include "ui/tables/editable_table_model.h"

namespace kerf::ui {

// A TNC table as a Qt model: one row per data row, one column per table column. Edits go through
// TncTable, which keeps the file's layout and refuses what the column cannot hold; every change
// can be undone. Headers show the column's unit where it has one. The whole-table check is the
// typed view's (ToolTable for TOOL.T ...), given by the caller.
class TncTableModel : public EditableTableModel {
    Q_OBJECT

public:
    using Validator = std::function<DiagnosticList(const tables::TncTable&)>;

    // Without a validator only the numeric columns are checked.
    explicit TncTableModel(tables::TncTable table, QObject* parent = nullptr,
                           Validator validator = {});

    const tables::TncTable& table() const { return m_table; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

    // Inserts a row before `row` with the next free key (one more than the largest numeric key).
    int insertKeyedRow(int row) override;
    bool removeTableRow(int row) override;
    void undo() override;
    bool modified() const override { return m_modified; }
    void setSaved() override { m_modified = false; }

    // Unit of a column: "mm"/"inch" for lengths, "°" for angles, "min" for times, "mm/min" for
    // feeds; empty if none.
    QString columnUnit(size_t column) const override;
    DiagnosticList validate() const override;
    std::string content() const override;

private:
    void remember();

    tables::TncTable m_table;
    std::vector<tables::TncTable> m_undo;
    Validator m_validator;
    bool m_modified = false;
};

}  // namespace kerf::ui
