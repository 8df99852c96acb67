#include "ui/settings/settings_model.h"

#include <QBrush>
#include <QColor>
#include <QCoreApplication>
#include <QFont>
#include <QRegularExpression>

#include "core/machine/machine_schema.h"

namespace kerf::ui {

namespace {

const char* const kCodeKey = "parameter_code";

constexpr size_t kMaxUndo = 200;

// The group of a key: "spindle" for "spindle.max_rpm", "axes.X" for "axes.X.max_velocity",
// empty for a top-level key.
std::string groupOf(const std::string& key) {
    const size_t dot = key.rfind('.');
    return dot == std::string::npos ? std::string() : key.substr(0, dot);
}

std::string nameOf(const std::string& key) {
    const size_t dot = key.rfind('.');
    return dot == std::string::npos ? key : key.substr(dot + 1);
}

// The typed value for the parameter's type. Text that is not of the type is passed on as text,
// so that the schema reports the wrong type with its own message naming the key.
machine::ParameterValue parseValue(const machine::ParameterDescriptor& descriptor,
                                   const QString& text) {
    using machine::ParameterType;
    static const QRegularExpression integer(QStringLiteral("^[+-]?\\d+$"));
    static const QRegularExpression number(QStringLiteral("^[+-]?(\\d+\\.?\\d*|\\.\\d+)$"));
    switch (descriptor.type) {
        case ParameterType::Number:
            if (number.match(text).hasMatch()) return text.toDouble();
            break;
        case ParameterType::Integer:
            if (integer.match(text).hasMatch()) return static_cast<int64_t>(text.toLongLong());
            break;
        case ParameterType::Bool:
            if (text == QLatin1String("true")) return true;
            if (text == QLatin1String("false")) return false;
            break;
        case ParameterType::String:
        case ParameterType::Enum:
            break;
    }
    return text.toStdString();
}

}  // namespace

SettingsModel::SettingsModel(machine::MachineConfig config, QObject* parent)
    : QAbstractTableModel(parent), m_config(std::move(config)) {
    buildRows();
}

void SettingsModel::buildRows() {
    m_rows.clear();
    std::string group = "-";  // no group yet
    for (const std::string& key : machine::parameterKeys(m_config)) {
        const std::string keyGroup = groupOf(key);
        if (keyGroup != group) {
            group = keyGroup;
            m_rows.push_back(Row{{}, group});
        }
        m_rows.push_back(Row{key, {}});
    }
}

QString SettingsModel::headingText(const std::string& group) {
    if (group.empty()) return tr("Machine");
    if (group.rfind("axes.", 0) == 0)
        return tr("Axis %1").arg(QString::fromStdString(group.substr(5)));
    return QString::fromStdString(group);
}

void SettingsModel::retranslate() {
    if (!m_rows.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
}

const std::string& SettingsModel::keyOf(int row) const {
    return m_rows.at(static_cast<size_t>(row)).key;
}

int SettingsModel::rowOf(const std::string& key) const {
    for (size_t i = 0; i < m_rows.size(); ++i) {
        if (m_rows[i].key == key) return static_cast<int>(i);
    }
    return -1;
}

int SettingsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int SettingsModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QString SettingsModel::valueText(const std::string& key) const {
    auto value = machine::getParameter(m_config, key);
    if (!value) return {};
    if (const auto* text = std::get_if<std::string>(&*value)) return QString::fromStdString(*text);
    return QString::fromStdString(machine::formatParameterValue(*value));
}

QVariant SettingsModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    const Row& row = m_rows.at(static_cast<size_t>(index.row()));
    if (row.key.empty()) {
        if (role == Qt::DisplayRole && index.column() == Name) return headingText(row.group);
        if (role == Qt::FontRole) {
            QFont bold;
            bold.setBold(true);
            return bold;
        }
        if (role == Qt::BackgroundRole) return QBrush(QColor(0xd9, 0xe2, 0xf3));
        return {};
    }
    if (role != Qt::DisplayRole && role != Qt::EditRole && role != Qt::ToolTipRole) return {};
    char letter = 0;
    const machine::ParameterDescriptor* descriptor = machine::findParameter(row.key, &letter);
    if (descriptor == nullptr) return {};
    const machine::AxisConfig* axis = letter != 0 ? m_config.axis(letter) : nullptr;
    const machine::AxisType axisType = axis ? axis->type : machine::AxisType::Linear;
    switch (index.column()) {
        case Name:
            return role == Qt::ToolTipRole ? QString::fromStdString(row.key)
                                           : QString::fromStdString(nameOf(row.key));
        case Value:
            // The code number itself is not shown to whoever has not given it.
            if (m_locked && row.key == kCodeKey) return QStringLiteral("****");
            return valueText(row.key);
        case Unit:
            return QString::fromStdString(
                std::string(machine::parameterUnit(*descriptor, axisType)));
        case Allowed:
            return QString::fromStdString(machine::formatAllowedValues(*descriptor, axisType));
        case Default:
            return QString::fromStdString(machine::formatParameterValue(descriptor->defaultValue));
        case Description:
            return QCoreApplication::translate("kerf", descriptor->description);
        default:
            return {};
    }
}

QVariant SettingsModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole || orientation != Qt::Horizontal) return {};
    switch (section) {
        case Name:
            return tr("Parameter");
        case Value:
            return tr("Value");
        case Unit:
            return tr("Unit");
        case Allowed:
            return tr("Allowed");
        case Default:
            return tr("Default");
        case Description:
            return tr("Description");
        default:
            return {};
    }
}

Qt::ItemFlags SettingsModel::flags(const QModelIndex& index) const {
    const Qt::ItemFlags base = QAbstractTableModel::flags(index);
    if (m_locked || !index.isValid() || isHeading(index.row()) || index.column() != Value)
        return base;
    return base | Qt::ItemIsEditable;
}

void SettingsModel::setLocked(bool locked) {
    if (locked == m_locked) return;
    m_locked = locked;
    emit dataChanged(index(0, Value), index(rowCount() - 1, Value));
}

bool SettingsModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || role != Qt::EditRole || index.column() != Value) return false;
    return setValueText(keyOf(index.row()), value.toString().trimmed());
}

bool SettingsModel::setValueText(const std::string& key, const QString& text) {
    const machine::ParameterDescriptor* descriptor = machine::findParameter(key);
    if (m_locked || descriptor == nullptr || text == valueText(key)) return false;
    machine::MachineConfig edited = m_config;
    if (MaybeError error = machine::setParameter(edited, key, parseValue(*descriptor, text))) {
        emit refused(*error);
        return false;
    }
    m_undo.push_back(std::move(m_config));
    if (m_undo.size() > kMaxUndo) m_undo.erase(m_undo.begin());
    m_config = std::move(edited);
    m_modified = true;
    const int row = rowOf(key);
    emit dataChanged(index(row, Value), index(row, Value));
    return true;
}

void SettingsModel::undo() {
    if (m_undo.empty()) return;
    beginResetModel();
    m_config = std::move(m_undo.back());
    m_undo.pop_back();
    buildRows();
    endResetModel();
    m_modified = true;
}

}  // namespace kerf::ui
