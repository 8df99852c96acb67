#include "ui/tables/fagor_table_model.h"

#include <QRegularExpression>
#include <cmath>

#include "core/base/translate.h"

namespace kerf::ui {

namespace {

constexpr size_t kMaxUndo = 200;

// "12.5", "-3", "+0,25": the numbers a FAGOR table holds (a comma is taken for the point).
std::optional<double> readNumber(QString text) {
    static const QRegularExpression number(QStringLiteral("^[+-]?(\\d+([.,]\\d*)?|[.,]\\d+)$"));
    if (!number.match(text).hasMatch()) return std::nullopt;
    text.replace(QLatin1Char(','), QLatin1Char('.'));
    return text.toDouble();
}

// Number of a key "<prefix><digits>", or -1.
int keyNumber(const std::string& key, const std::string& prefix) {
    if (key.size() <= prefix.size() || key.compare(0, prefix.size(), prefix) != 0) return -1;
    int n = 0;
    for (size_t i = prefix.size(); i < key.size(); ++i) {
        if (key[i] < '0' || key[i] > '9' || n > 99999) return -1;
        n = n * 10 + (key[i] - '0');
    }
    return n;
}

}  // namespace

FagorTableModel::FagorTableModel(fagor::TableText text, FagorTableSpec spec, QObject* parent)
    : EditableTableModel(parent), m_text(std::move(text)), m_spec(std::move(spec)) {
    refreshKeys();
}

void FagorTableModel::refreshKeys() {
    if (!m_spec.fixedKeys.empty()) {
        m_keys = m_spec.fixedKeys;
        return;
    }
    m_keys.clear();
    for (const fagor::TableRow& row : m_text.rows()) {
        if (keyNumber(row.key, m_spec.keyPrefix) >= 0) m_keys.push_back(row.key);
    }
}

int FagorTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_keys.size());
}

int FagorTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(m_spec.columns.size() + 1);
}

QVariant FagorTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid()) return {};
    const std::string& key = keyOf(index.row());
    if (role == Qt::TextAlignmentRole && index.column() > 0) {
        return QVariant(Qt::AlignRight | Qt::AlignVCenter);
    }
    if (role != Qt::DisplayRole && role != Qt::EditRole) return {};
    if (index.column() == 0) return QString::fromStdString(key);
    const FagorColumn& column = m_spec.columns.at(static_cast<size_t>(index.column() - 1));
    double value = 0.0;
    if (const fagor::TableRow* row = m_text.row(key)) {
        if (const fagor::TableField* field = row->field(column.field)) value = field->value;
    }
    return QString::fromStdString(fagor::formatTableNumber(value));
}

QVariant FagorTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (role != Qt::DisplayRole) return {};
    if (orientation == Qt::Vertical) return section + 1;
    if (section == 0) return tr("Key");
    if (section < 0 || section > static_cast<int>(m_spec.columns.size())) return {};
    const FagorColumn& column = m_spec.columns[static_cast<size_t>(section - 1)];
    const QString name = QString::fromStdString(column.field);
    return column.unit.isEmpty() ? name : QStringLiteral("%1\n[%2]").arg(name, column.unit);
}

Qt::ItemFlags FagorTableModel::flags(const QModelIndex& index) const {
    const Qt::ItemFlags base = EditableTableModel::flags(index);
    return index.column() == 0 ? base : base | Qt::ItemIsEditable;
}

Diagnostic FagorTableModel::fieldError(const std::string& key, const std::string& field,
                                       const char* messageTemplate,
                                       std::vector<std::string> args) const {
    // At the field when the file has it, else at its row, else at the file.
    size_t line = 0;
    size_t column = 0;
    if (const fagor::TableRow* row = m_text.row(key)) {
        line = row->line + 1;
        column = 1;
        if (const fagor::TableField* f = row->field(field)) column = f->offset + 1;
    }
    Diagnostic d =
        Diagnostic::make(Severity::Error, "table", m_text.fileName(), static_cast<uint32_t>(line),
                         static_cast<uint32_t>(column), messageTemplate);
    d.args = std::move(args);
    return d;
}

bool FagorTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || index.column() == 0 || role != Qt::EditRole) return false;
    const std::string& key = keyOf(index.row());
    const FagorColumn& column = m_spec.columns.at(static_cast<size_t>(index.column() - 1));
    const QString text = value.toString().trimmed();
    const std::optional<double> number = readNumber(text);
    const std::string where = key + " " + column.field;
    if (!number) {
        emit refused(fieldError(key, column.field, KERF_TR_NOOP("{1} needs a number, not \"{2}\""),
                                {where, text.toStdString()}));
        return false;
    }
    const bool whole = !column.integer || *number == std::floor(*number);
    if (!whole || *number < column.minimum || *number > column.maximum) {
        emit refused(fieldError(key, column.field,
                                column.integer
                                    ? KERF_TR_NOOP("{1} must be a whole number from {2} to {3}")
                                    : KERF_TR_NOOP("{1} must be from {2} to {3}"),
                                {where, fagor::formatTableNumber(column.minimum),
                                 fagor::formatTableNumber(column.maximum)}));
        return false;
    }
    if (data(index, Qt::EditRole).toString() ==
            QString::fromStdString(fagor::formatTableNumber(*number)) &&
        m_text.row(key) != nullptr) {
        return false;  // no change
    }
    fagor::TableText edited = m_text;
    edited.set(key, column.field, *number);
    if (m_spec.validate) {
        if (MaybeError error = m_spec.validate(edited)) {
            emit refused(*error);
            return false;
        }
    }
    commit(std::move(edited));
    return true;
}

void FagorTableModel::commit(fagor::TableText edited) {
    beginResetModel();
    m_undo.push_back(std::move(m_text));
    if (m_undo.size() > kMaxUndo) m_undo.erase(m_undo.begin());
    m_text = std::move(edited);
    refreshKeys();
    endResetModel();
    m_modified = true;
}

int FagorTableModel::insertKeyedRow(int /*row: new rows go to the end of the file*/) {
    if (m_spec.keyPrefix.empty()) {
        emit refused(fieldError({}, {},
                                KERF_TR_NOOP("this table has a fixed row for every entry: edit "
                                             "the values instead"),
                                {}));
        return -1;
    }
    int largest = m_spec.firstKey - 1;
    for (const std::string& key : m_keys)
        largest = std::max(largest, keyNumber(key, m_spec.keyPrefix));
    int next = largest + 1;
    // Past the last number: the first gap.
    for (int n = m_spec.firstKey; next > m_spec.lastKey && n <= m_spec.lastKey; ++n) {
        if (m_text.row(m_spec.keyPrefix + std::to_string(n)) == nullptr) next = n;
    }
    if (next > m_spec.lastKey) {
        emit refused(fieldError(
            {}, {}, KERF_TR_NOOP("the table is full ({1}{2} to {1}{3})"),
            {m_spec.keyPrefix, std::to_string(m_spec.firstKey), std::to_string(m_spec.lastKey)}));
        return -1;
    }
    // Every field written, zero; a tool uses the offset with its own number (T5 -> D5).
    std::string fields;
    for (const FagorColumn& column : m_spec.columns) {
        const bool ownOffset = m_spec.keyPrefix == "T" && column.field == "D";
        fields +=
            (fields.empty() ? "" : " ") + column.field + (ownOffset ? std::to_string(next) : "0");
    }
    fagor::TableText edited = m_text;
    edited.replaceRow(m_spec.keyPrefix + std::to_string(next), fields);
    commit(std::move(edited));
    return rowCount() - 1;
}

bool FagorTableModel::removeTableRow(int row) {
    if (row < 0 || row >= rowCount()) return false;
    if (m_spec.keyPrefix.empty()) {
        emit refused(fieldError({}, {},
                                KERF_TR_NOOP("this table has a fixed row for every entry: edit "
                                             "the values instead"),
                                {}));
        return false;
    }
    fagor::TableText edited = m_text;
    if (!edited.removeRow(keyOf(row))) return false;
    commit(std::move(edited));
    return true;
}

void FagorTableModel::undo() {
    if (m_undo.empty()) return;
    beginResetModel();
    m_text = std::move(m_undo.back());
    m_undo.pop_back();
    refreshKeys();
    endResetModel();
    m_modified = true;
}

QString FagorTableModel::columnUnit(size_t column) const {
    return column == 0 || column > m_spec.columns.size() ? QString()
                                                         : m_spec.columns[column - 1].unit;
}

DiagnosticList FagorTableModel::validate() const {
    if (!m_spec.validate) return {};
    MaybeError error = m_spec.validate(m_text);
    return error ? DiagnosticList{*error} : DiagnosticList{};
}

std::string FagorTableModel::content() const {
    return m_text.serialize();
}

}  // namespace kerf::ui
