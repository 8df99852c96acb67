#include "ui/settings/mod_page.h"

#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QSettings>
#include <QVBoxLayout>
#include <array>

namespace kerf::ui {

namespace {

constexpr std::array<PositionKind, 6> kKinds = {
    PositionKind::Actual,           PositionKind::Nominal, PositionKind::ReferenceActual,
    PositionKind::ReferenceNominal, PositionKind::Lag,     PositionKind::DistanceToGo,
};

// KERF_VERSION is the bare version number (0.1.0) from CMake: made a string here.
#define KERF_STRING(x) #x
#define KERF_EXPANDED_STRING(x) KERF_STRING(x)

const char* const kPositionKey = "mod/position_display";
const char* const kInchKey = "mod/inch";

QComboBox* makeCombo(QWidget* parent) {
    auto* combo = new QComboBox(parent);
    combo->setMinimumHeight(48);  // a finger's target
    combo->setMinimumWidth(220);
    return combo;
}

}  // namespace

QString ModPage::positionKindName(PositionKind kind) {
    switch (kind) {
        case PositionKind::Actual:
            return QStringLiteral("ACTL");
        case PositionKind::Nominal:
            return QStringLiteral("NOML");
        case PositionKind::ReferenceActual:
            return QStringLiteral("REF ACTL");
        case PositionKind::ReferenceNominal:
            return QStringLiteral("REF NOML");
        case PositionKind::Lag:
            return QStringLiteral("LAG");
        case PositionKind::DistanceToGo:
            return QStringLiteral("DIST");
    }
    return {};
}

ModPage::ModPage(const machine::MachineConfig& machine, const QString& settingsFile,
                 QWidget* parent)
    : QWidget(parent),
      m_settings(settingsFile.isEmpty()
                     ? std::make_unique<QSettings>(QSettings::IniFormat, QSettings::UserScope,
                                                   QStringLiteral("kerf"), QStringLiteral("hmi"))
                     : std::make_unique<QSettings>(settingsFile, QSettings::IniFormat)) {
    setObjectName("modPage");
    qRegisterMetaType<kerf::ui::DisplaySettings>("kerf::ui::DisplaySettings");
    // The choices of the last session; unknown names fall back to ACTL.
    const QString stored = m_settings->value(kPositionKey).toString();
    for (PositionKind kind : kKinds) {
        if (positionKindName(kind) == stored) m_display.positionKind = kind;
    }
    m_display.inch = m_settings->value(kInchKey, false).toBool();
    m_machineText = QStringLiteral("%1 (%2), %3")
                        .arg(QString::fromStdString(machine.name),
                             machine.kind == machine::MachineKind::Lathe ? QStringLiteral("lathe")
                                                                         : QStringLiteral("mill"),
                             QString::fromStdString(machine.enabledAxisLetters()));

    auto* layout = new QVBoxLayout(this);
    m_title = new QLabel(this);
    m_title->setStyleSheet(QStringLiteral("font-weight: bold; font-size: 16px;"));
    layout->addWidget(m_title);
    auto* form = new QFormLayout();
    m_position = makeCombo(this);
    m_position->setObjectName("modPosition");
    for (PositionKind kind : kKinds)
        m_position->addItem(positionKindName(kind), static_cast<int>(kind));
    m_position->setCurrentIndex(m_position->findData(static_cast<int>(m_display.positionKind)));
    m_unit = makeCombo(this);
    m_unit->setObjectName("modUnit");
    m_unit->addItem(QStringLiteral("mm"), false);
    m_unit->addItem(QStringLiteral("inch"), true);
    m_unit->setCurrentIndex(m_display.inch ? 1 : 0);
    m_language = makeCombo(this);
    m_language->setObjectName("modLanguage");
    m_positionLabel = new QLabel(this);
    m_unitLabel = new QLabel(this);
    m_languageLabel = new QLabel(this);
    form->addRow(m_positionLabel, m_position);
    form->addRow(m_unitLabel, m_unit);
    form->addRow(m_languageLabel, m_language);
    layout->addLayout(form);
    m_info = new QLabel(this);
    m_info->setObjectName("modInfo");
    m_info->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_info->setWordWrap(true);  // long texts never widen the window
    layout->addWidget(m_info);
    layout->addStretch(1);

    connect(m_position, qOverload<int>(&QComboBox::activated), this, [this](int index) {
        setPositionKind(static_cast<PositionKind>(m_position->itemData(index).toInt()));
    });
    connect(m_unit, qOverload<int>(&QComboBox::activated), this,
            [this](int index) { setInch(m_unit->itemData(index).toBool()); });
    connect(m_language, qOverload<int>(&QComboBox::activated), this,
            [this](int index) { emit languageRequested(m_language->itemData(index).toString()); });
    retranslate();
}

ModPage::~ModPage() = default;

void ModPage::setPositionKind(PositionKind kind) {
    m_position->setCurrentIndex(m_position->findData(static_cast<int>(kind)));
    if (kind == m_display.positionKind) return;
    m_display.positionKind = kind;
    store();
}

void ModPage::setInch(bool inch) {
    m_unit->setCurrentIndex(inch ? 1 : 0);
    if (inch == m_display.inch) return;
    m_display.inch = inch;
    store();
}

void ModPage::store() {
    m_settings->setValue(kPositionKey, positionKindName(m_display.positionKind));
    m_settings->setValue(kInchKey, m_display.inch);
    m_settings->sync();
    emit displaySettingsChanged(m_display);
}

void ModPage::setLanguages(const QStringList& codes, const QString& current) {
    m_language->clear();
    for (const QString& code : codes)
        m_language->addItem(code.toUpper(), code);
    m_language->setCurrentIndex(m_language->findData(current));
}

void ModPage::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void ModPage::retranslate() {
    m_title->setText(tr("MOD functions"));
    m_positionLabel->setText(tr("Position display"));
    m_unitLabel->setText(tr("Unit of the position display"));
    m_languageLabel->setText(tr("Language"));
    m_info->setText(tr("Software: Kerf %1 (Qt %2)\nMachine: %3")
                        .arg(QStringLiteral(KERF_EXPANDED_STRING(KERF_VERSION)),
                             QString::fromLatin1(qVersion()), m_machineText) +
                    QStringLiteral("\n\n") +
                    tr("Kerf is free software: you may share and change it under the GNU General "
                       "Public License, version 3 or later. It comes with no warranty."));
}

}  // namespace kerf::ui
