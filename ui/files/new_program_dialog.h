#pragma once

#include <QDialog>
#include <array>

#include "core/machine/machine_config.h"
#include "ui/files/new_program.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;

namespace kerf::ui {

// "New program", as the TNC asks it: the name, MM or INCH and, on a mill, the blank (BLK FORM)
// as its MIN and MAX points; on a lathe (FAGOR) the name and the unit. OK refuses an empty name
// or a blank whose MIN is not below its MAX, saying why in red. Fields and buttons are touch
// sized (48 px).
class NewProgramDialog : public QDialog {
    Q_OBJECT

public:
    NewProgramDialog(const machine::MachineConfig& machine, QWidget* parent = nullptr);

    NewProgramSpec spec() const;
    QLineEdit* nameField() const { return m_name; }
    QComboBox* unitField() const { return m_unit; }
    // Blank MIN (0-2) and MAX (3-5) as X Y Z; none on a lathe.
    QDoubleSpinBox* blankField(int index) const { return m_blank[static_cast<size_t>(index)]; }
    QLabel* problem() const { return m_problem; }

    void accept() override;

private:
    QLineEdit* m_name = nullptr;
    QComboBox* m_unit = nullptr;
    std::array<QDoubleSpinBox*, 6> m_blank{};
    QLabel* m_problem = nullptr;
};

}  // namespace kerf::ui
