#pragma once

#include <QMainWindow>

class QLabel;

namespace kerf::ui {

// The operator panel's frame: a header naming the machine and programming modes, the workspace
// and the softkey row. The HMI issue fills the workspace; this is the minimal shell.
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(const QString& machineName, QWidget* parent = nullptr);

private:
    QLabel* m_machineMode = nullptr;
    QLabel* m_programmingMode = nullptr;
};

}  // namespace kerf::ui
