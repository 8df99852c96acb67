#include "ui/settings/settings_page.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>
#include <algorithm>

#include "core/machine/machine_validation.h"
#include "core/machine/machine_writer.h"
#include "ui/common/diagnostic_text.h"
#include "ui/settings/settings_model.h"

namespace kerf::ui {

SettingsPage::SettingsPage(machine::MachineConfig config, std::filesystem::path file, bool builtIn,
                           QWidget* parent)
    : QWidget(parent), m_file(std::move(file)), m_builtIn(builtIn), m_code(config.parameterCode) {
    setObjectName("settingsPage");
    registerDiagnosticMetaTypes();
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_title = new QLabel(this);
    m_title->setStyleSheet(QStringLiteral("font-weight: bold; font-size: 16px;"));
    m_note = new QLabel(this);
    m_note->setWordWrap(true);
    m_note->setStyleSheet(QStringLiteral("background: #fff4ce; padding: 6px;"));
    layout->addWidget(m_title);
    layout->addWidget(m_note);
    m_codeRow = new QWidget(this);
    auto* codeLayout = new QHBoxLayout(m_codeRow);
    codeLayout->setContentsMargins(0, 0, 0, 0);
    m_codeLabel = new QLabel(m_codeRow);
    m_codeEdit = new QLineEdit(m_codeRow);
    m_codeEdit->setObjectName("settingsCode");
    m_codeEdit->setEchoMode(QLineEdit::Password);
    m_codeEdit->setMinimumHeight(48);  // a finger's target
    m_codeEdit->setMaximumWidth(200);
    m_unlockButton = new QPushButton(m_codeRow);
    m_unlockButton->setObjectName("settingsUnlock");
    m_unlockButton->setMinimumHeight(48);
    codeLayout->addWidget(m_codeLabel);
    codeLayout->addWidget(m_codeEdit);
    codeLayout->addWidget(m_unlockButton);
    codeLayout->addStretch(1);
    layout->addWidget(m_codeRow);
    const auto tryCode = [this] {
        unlock(m_codeEdit->text());
        m_codeEdit->clear();
    };
    connect(m_codeEdit, &QLineEdit::returnPressed, this, tryCode);
    connect(m_unlockButton, &QPushButton::clicked, this, tryCode);
    m_model = new SettingsModel(std::move(config), this);
    m_model->setLocked(true);
    connect(m_model, &SettingsModel::refused, this, &SettingsPage::report);
    m_view = new QTableView(this);
    m_view->setObjectName("settingsView");
    m_view->setModel(m_model);
    m_view->verticalHeader()->hide();
    // Descriptions wrap onto as many lines as they need, never cut with "...": each row is as
    // high as its text at the description column's width (at least a finger's target).
    m_view->setWordWrap(true);
    m_view->verticalHeader()->setMinimumSectionSize(36);
    m_view->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_view->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(m_view, 1);
    retranslate();
    m_view->resizeColumnsToContents();
    // Long allowed ranges must not push the description off the screen; tooltips hold it all.
    for (int column = 0; column < SettingsModel::Description; ++column)
        m_view->setColumnWidth(column, std::min(m_view->columnWidth(column), 220));
}

bool SettingsPage::unlock(const QString& code) {
    bool ok = false;
    const int given = code.trimmed().toInt(&ok);
    if (!ok || given != m_code) {
        emit message(Severity::Error, tr("Wrong code number: the machine parameters stay locked"));
        return false;
    }
    m_model->setLocked(false);
    m_codeRow->hide();
    emit message(Severity::Note, tr("Machine parameters unlocked for editing"));
    return true;
}

bool SettingsPage::locked() const {
    return m_model->locked();
}

bool SettingsPage::modified() const {
    return m_model->modified();
}

void SettingsPage::undo() {
    m_model->undo();
}

bool SettingsPage::save() {
    // The rules that relate parameters (limits min < max ...) are checked only as a whole.
    const DiagnosticList problems = machine::validateMachine(m_model->config());
    if (hasErrors(problems)) {
        for (const Diagnostic& d : problems)
            report(d);
        emit message(Severity::Error, tr("Not saved: correct the parameters first"));
        return false;
    }
    if (const MaybeError error = machine::saveMachine(m_model->config(), m_file)) {
        report(*error);
        return false;
    }
    m_model->setSaved();
    emit message(Severity::Note, tr("Saved %1: the changes apply when Kerf is restarted")
                                     .arg(QString::fromStdString(m_file.string())));
    return true;
}

void SettingsPage::report(const Diagnostic& d) {
    emit message(d.severity, translatedMessage(d));
}

void SettingsPage::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void SettingsPage::retranslate() {
    m_title->setText(tr("Machine parameters"));
    m_codeLabel->setText(tr("Code number for editing"));
    m_unlockButton->setText(tr("Unlock"));
    m_model->retranslate();
    const QString file = QString::fromStdString(m_file.string());
    m_note->setText(
        m_builtIn
            ? tr("Kerf reads the machine parameters when it starts: saved changes apply after a "
                 "restart. This is a built-in machine: the parameters are saved to %1; start "
                 "Kerf with --machine %1 to use them.")
                  .arg(file)
            : tr("Kerf reads the machine parameters when it starts: saved changes to %1 apply "
                 "after a restart.")
                  .arg(file));
}

}  // namespace kerf::ui
