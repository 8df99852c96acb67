#include "ui/shell/main_window.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace kerf::ui {

MainWindow::MainWindow(const QString& machineName, QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(tr("Kerf - %1").arg(machineName));
    auto* central = new QWidget(this);
    auto* layout = new QVBoxLayout(central);

    auto* header = new QHBoxLayout();
    m_machineMode = new QLabel(tr("Manual operation"), central);
    m_programmingMode = new QLabel(tr("Programming"), central);
    m_machineMode->setObjectName("machineMode");
    m_programmingMode->setObjectName("programmingMode");
    header->addWidget(m_machineMode);
    header->addStretch();
    header->addWidget(m_programmingMode);
    layout->addLayout(header);

    auto* workspace = new QLabel(tr("Simulated machine: %1").arg(machineName), central);
    workspace->setAlignment(Qt::AlignCenter);
    workspace->setObjectName("workspace");
    layout->addWidget(workspace, 1);

    auto* softkeys = new QHBoxLayout();
    for (int i = 1; i <= 8; ++i) {
        auto* key = new QPushButton(QStringLiteral("F%1").arg(i), central);
        key->setMinimumHeight(48);
        softkeys->addWidget(key);
    }
    layout->addLayout(softkeys);
    setCentralWidget(central);
    resize(1280, 800);
}

}  // namespace kerf::ui
