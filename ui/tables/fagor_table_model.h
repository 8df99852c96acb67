#pragma once

#include <string>
#include <vector>

#include "core/interp/fagor/tables/table_text.h"
#include "ui/tables/editable_table_model.h"
#include "ui/tables/fagor_table_spec.h"

namespace kerf::ui {

// A FAGOR table (tool offsets, zero offsets, tools) as a Qt model: column 0 is the row key
// (D3, G54, T5), the others the spec's fields. A field the file does not have reads 0, as on the
// control. Edits rewrite only the field they touch (TableText), are checked against the column
// (whole numbers, range) and then by the typed table, and can be undone. New rows go to the end
// of the file.
class FagorTableModel : public EditableTableModel {
    Q_OBJECT

public:
    FagorTableModel(fagor::TableText text, FagorTableSpec spec, QObject* parent = nullptr);

    const fagor::TableText& text() const { return m_text; }
    const std::string& keyOf(int row) const { return m_keys.at(static_cast<size_t>(row)); }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

    int insertKeyedRow(int row) override;
    bool removeTableRow(int row) override;
    void undo() override;
    bool modified() const override { return m_modified; }
    void setSaved() override { m_modified = false; }
    QString columnUnit(size_t column) const override;
    DiagnosticList validate() const override;
    std::string content() const override;

private:
    void refreshKeys();
    // Replaces the text after an edit, remembering the old one for undo.
    void commit(fagor::TableText edited);
    Diagnostic fieldError(const std::string& key, const std::string& field,
                          const char* messageTemplate, std::vector<std::string> args) const;

    fagor::TableText m_text;
    FagorTableSpec m_spec;
    std::vector<std::string> m_keys;
    std::vector<fagor::TableText> m_undo;
    bool m_modified = false;
};

}  // namespace kerf::ui
