#pragma once

#include <QDialog>
#include <vector>

#include "core/cycles/cycle_descriptor.h"
#include "ui/cycles/cycle_catalogue.h"

class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace kerf::ui {

// The cycle overview: the TNC's groups as touch buttons, the group's cycles (number and name
// in the UI language) in a list, and a field to pick a cycle by number (Enter).
class CycleCatalogueDialog : public QDialog {
    Q_OBJECT

public:
    explicit CycleCatalogueDialog(QWidget* parent = nullptr);

    void showGroup(int section);
    QListWidget* list() const { return m_list; }
    QLineEdit* numberInput() const { return m_number; }
    const cycles::CycleDescriptor* selectedCycle() const { return m_selected; }

    void accept() override;

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void chooseNumber();

    std::vector<CatalogueSection> m_sections;
    std::vector<QPushButton*> m_groups;
    QListWidget* m_list = nullptr;
    QLineEdit* m_number = nullptr;
    QLabel* m_numberLabel = nullptr;
    QLabel* m_message = nullptr;
    QPushButton* m_ok = nullptr;
    QPushButton* m_cancel = nullptr;
    int m_section = 0;
    const cycles::CycleDescriptor* m_selected = nullptr;
};

}  // namespace kerf::ui
