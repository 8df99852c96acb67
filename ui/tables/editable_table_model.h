#pragma once

#include <QAbstractTableModel>
#include <QString>
#include <filesystem>

#include "core/base/diagnostic.h"
#include "core/base/expected.h"

namespace kerf::ui {

// What the table editor needs from a table, whatever its file format (TNC fixed-width tables,
// FAGOR key-and-field tables): cells edited in place and refused with a diagnostic, rows
// inserted and removed, every change undoable, whole-table validation and an atomic save.
class EditableTableModel : public QAbstractTableModel {
    Q_OBJECT

public:
    using QAbstractTableModel::QAbstractTableModel;

    // Inserts a row with the next free key before `row` (where the format allows; FAGOR rows go
    // to the end). Returns the new row, or -1 when refused.
    virtual int insertKeyedRow(int row) = 0;
    virtual bool removeTableRow(int row) = 0;
    virtual void undo() = 0;
    virtual bool modified() const = 0;
    virtual void setSaved() = 0;

    // Unit of a column ("mm", "°", "mm/min" ...); empty if none.
    virtual QString columnUnit(size_t column) const = 0;
    // Problems that block a save; empty when the table is fine.
    virtual DiagnosticList validate() const = 0;
    // The file's text as it is saved (the table editor writes it through the NC root).
    virtual std::string content() const = 0;

    // Row whose cells contain `text` (case-insensitive), searching from `from` on and wrapping.
    int findRow(const QString& text, int from) const;

signals:
    void refused(const kerf::Diagnostic& reason);
};

}  // namespace kerf::ui
