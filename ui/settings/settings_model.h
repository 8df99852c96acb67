#pragma once

#include <QAbstractTableModel>
#include <string>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/machine/machine_config.h"

namespace kerf::ui {

// The machine parameters as a table generated from the schema (core/machine/machine_schema):
// a heading row per group ("Machine", "spindle", "Axis X" ...) followed by one row per
// parameter with its value, unit, allowed values, default and description. Only the value is
// editable, and only while not locked; it is checked by the schema's setParameter, whose message
// names the key. Every accepted change can be undone.
class SettingsModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { Name, Value, Unit, Allowed, Default, Description, ColumnCount };

    explicit SettingsModel(machine::MachineConfig config, QObject* parent = nullptr);

    const machine::MachineConfig& config() const { return m_config; }
    // Full key of a row ("axes.X.max_velocity"); empty for a heading row.
    const std::string& keyOf(int row) const;
    int rowOf(const std::string& key) const;
    bool isHeading(int row) const { return keyOf(row).empty(); }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

    // Sets a parameter from its text as typed ("12000", "true", "lathe").
    bool setValueText(const std::string& key, const QString& text);
    void undo();
    bool modified() const { return m_modified; }
    // Locked: the values are shown but not editable (the code number is not yet given).
    void setLocked(bool locked);
    bool locked() const { return m_locked; }
    void setSaved() { m_modified = false; }
    // The language changed: the views fetch the headings and descriptions again.
    void retranslate();

signals:
    void refused(const kerf::Diagnostic& reason);

private:
    struct Row {
        std::string key;    // empty: heading
        std::string group;  // heading rows only: "" (top level), "spindle", "axes.X" ...
    };
    void buildRows();
    // In the language shown now (the rows are made before the language is chosen).
    static QString headingText(const std::string& group);
    QString valueText(const std::string& key) const;

    machine::MachineConfig m_config;
    std::vector<Row> m_rows;
    std::vector<machine::MachineConfig> m_undo;
    bool m_modified = false;
    bool m_locked = false;
};

}  // namespace kerf::ui
