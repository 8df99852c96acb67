#include "ui/cycles/cycle_dialog.h"

#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

#include "ui/cycles/cycle_block.h"
#include "ui/cycles/cycle_catalogue.h"
#include "ui/cycles/cycle_help_picture.h"
#include "ui/cycles/dialog_parts.h"

namespace kerf::ui {

namespace {

QString rangeText(const CycleField& field, bool inch) {
    const cycles::ParameterDescriptor& p = *field.parameter;
    if (p.unit == cycles::Unit::Text || field.style == WordStyle::Bare) return {};
    QString text =
        QStringLiteral("%1 … %2").arg(formatNumber(inProgramUnit(p, p.min, inch), false),
                                      formatNumber(inProgramUnit(p, p.max, inch), false));
    QStringList keywords;
    if (p.predef) keywords << QStringLiteral("PREDEF");
    if (p.keywords & cycles::kFeedAuto) keywords << QStringLiteral("FAUTO");
    if (p.keywords & cycles::kFeedMax) keywords << QStringLiteral("FMAX");
    if (p.keywords & cycles::kFeedPerRev) keywords << QStringLiteral("FU");
    if (p.keywords & cycles::kFeedPerTooth) keywords << QStringLiteral("FZ");
    // The keywords on a line of their own: the column stays as narrow as the numbers and the
    // descriptions get the rest of the row.
    if (!keywords.isEmpty()) text += QLatin1Char('\n') + keywords.join(QLatin1Char(' '));
    return text;
}

}  // namespace

CycleDialog::CycleDialog(const cycles::CycleDescriptor& cycle, bool inch, QWidget* parent)
    : QDialog(parent), m_cycle(cycle), m_inch(inch), m_fields(cycleFields(cycle)) {
    setObjectName("cycleDialog");
    auto* outer = new QHBoxLayout(this);
    auto* left = new QVBoxLayout;
    outer->addLayout(left, 3);

    m_title = new QLabel(this);
    m_title->setObjectName("cycleTitle");
    m_title->setStyleSheet(QStringLiteral("font-weight: bold; font-size: 16px;"));
    left->addWidget(m_title);

    auto* rows = new QWidget;
    auto* grid = new QGridLayout(rows);
    grid->setColumnStretch(1, 1);
    for (size_t i = 0; i < m_fields.size(); ++i) {
        const int row = static_cast<int>(i);
        auto* label = new QLabel(m_fields[i].label, rows);
        label->setStyleSheet(QStringLiteral("font-weight: bold;"));
        auto* description = new QLabel(rows);
        description->setObjectName(QStringLiteral("description_%1").arg(m_fields[i].label));
        description->setWordWrap(true);
        auto* input = new QLineEdit(defaultText(m_fields[i], inch), rows);
        input->setObjectName(QStringLiteral("field_%1").arg(m_fields[i].label));
        input->setMinimumHeight(kTouchHeight);
        input->setMinimumWidth(120);
        input->installEventFilter(this);
        connect(input, &QLineEdit::returnPressed, this, [this, row] { enterPressed(row); });
        auto* unit = new QLabel(unitText(m_fields[i].parameter->unit, inch), rows);
        auto* range = new QLabel(rows);
        range->setObjectName(QStringLiteral("range_%1").arg(m_fields[i].label));
        range->setStyleSheet(QStringLiteral("color: #606060;"));
        grid->addWidget(label, row, 0);
        grid->addWidget(description, row, 1);
        grid->addWidget(input, row, 2);
        grid->addWidget(unit, row, 3);
        grid->addWidget(range, row, 4);
        m_inputs.push_back(input);
        m_descriptions.push_back(description);
        m_ranges.push_back(range);
    }
    auto* scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("cycleFields"));
    scroll->setWidget(rows);
    scroll->setWidgetResizable(true);
    left->addWidget(scroll, 1);

    m_message = addRefusalLine(*this, *left, "cycleMessage");
    addOkCancel(*this, *left, m_ok, m_cancel);

    auto* right = new QVBoxLayout;
    m_picture = new CycleHelpPicture(this);
    m_picture->setCycle(cycle);
    right->addWidget(m_picture, 1);
    m_fieldHelp = new QLabel(this);
    m_fieldHelp->setObjectName("cycleFieldHelp");
    m_fieldHelp->setWordWrap(true);
    right->addWidget(m_fieldHelp);
    outer->addLayout(right, 2);

    retranslate();
    sizeToWindow(*this);
    if (!m_inputs.empty()) {
        setCurrentField(0);
        m_inputs.front()->setFocus();
    }
}

void CycleDialog::setValues(const QStringList& values) {
    for (size_t i = 0; i < m_inputs.size(); ++i)
        m_inputs[i]->setText(values.value(static_cast<int>(i)));
}

QStringList CycleDialog::values() const {
    QStringList list;
    for (const QLineEdit* input : m_inputs)
        list << input->text().trimmed();
    return list;
}

QStringList CycleDialog::blocks() const {
    return writeCycleBlocks(m_cycle, m_fields, values());
}

void CycleDialog::setCurrentField(int field) {
    if (field < 0 || field >= fieldCount()) return;
    m_current = field;
    const CycleField& f = m_fields[static_cast<size_t>(field)];
    m_picture->setField(f.label);
    m_fieldHelp->setText(QStringLiteral("%1: %2").arg(f.label, parameterDescription(*f.parameter)));
}

QString CycleDialog::message() const {
    return m_message->text();
}

bool CycleDialog::checkField(int field) {
    const auto error = checkFieldText(m_cycle, m_fields[static_cast<size_t>(field)],
                                      m_inputs[static_cast<size_t>(field)]->text(), m_inch);
    if (!error) {
        m_message->clear();
        return true;
    }
    m_message->setText(*error);
    setCurrentField(field);
    m_inputs[static_cast<size_t>(field)]->setFocus();
    m_inputs[static_cast<size_t>(field)]->selectAll();
    return false;
}

void CycleDialog::enterPressed(int field) {
    if (!checkField(field)) return;
    if (field + 1 < fieldCount()) {
        setCurrentField(field + 1);
        m_inputs[static_cast<size_t>(field + 1)]->setFocus();
        m_inputs[static_cast<size_t>(field + 1)]->selectAll();
        return;
    }
    accept();
}

void CycleDialog::accept() {
    for (int i = 0; i < fieldCount(); ++i) {
        if (!checkField(i)) return;
    }
    QDialog::accept();
}

void CycleDialog::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QDialog::changeEvent(event);
}

bool CycleDialog::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::FocusIn) {
        for (size_t i = 0; i < m_inputs.size(); ++i) {
            if (m_inputs[i] == watched) setCurrentField(static_cast<int>(i));
        }
    }
    return QDialog::eventFilter(watched, event);
}

void CycleDialog::retranslate() {
    setWindowTitle(tr("Cycle definition"));
    m_title->setText(QStringLiteral("CYCL DEF %1").arg(cycleTitle(m_cycle)));
    for (size_t i = 0; i < m_fields.size(); ++i) {
        m_descriptions[i]->setText(parameterDescription(*m_fields[i].parameter));
        m_ranges[i]->setText(rangeText(m_fields[i], m_inch));
    }
    m_ok->setText(tr("OK"));
    m_cancel->setText(tr("Cancel"));
    setCurrentField(m_current);
}

}  // namespace kerf::ui
