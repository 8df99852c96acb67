#pragma once

#include <QAbstractTableModel>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/tables/tnc_table.h"

namespace kerf::ui {

// A TNC table as a Qt model: one row per data row, one column per table column. Edits go through
// TncTable, which keeps the file's layout and refuses what the column cannot hold; every change
// can be undone. Headers show the column's unit where it has one.
class TncTableModel : public QAbstractTableModel {
    Q_OBJECT

public:
    explicit TncTableModel(tables::TncTable table, QObject* parent = nullptr);

    const tables::TncTable& table() const { return m_table; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

    // Inserts a row before `row` with the next free key (one more than the largest numeric key).
    bool insertKeyedRow(int row);
    bool removeTableRow(int row);
    void undo();
    bool modified() const { return m_modified; }
    void setSaved() { m_modified = false; }

    // Unit of a column: "mm"/"inch" for lengths, "°" for angles, "min" for times; empty if none.
    QString columnUnit(size_t column) const;
    // Row whose cells contain `text` (case-insensitive), searching from `from` on and wrapping.
    int findRow(const QString& text, int from) const;

signals:
    void refused(const kerf::Diagnostic& reason);

private:
    void remember();

    tables::TncTable m_table;
    std::vector<tables::TncTable> m_undo;
    bool m_modified = false;
};

}  // namespace kerf::ui
