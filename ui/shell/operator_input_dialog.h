#pragma once

#include <QDialog>
#include <utility>
#include <vector>

class QLineEdit;

namespace kerf::ui {

// Asks the operator for the IBn values a FAGOR program reads before it starts (docs/fagor.md,
// "Operator inputs"): one field per variable, filled with the value it has now.
class OperatorInputDialog : public QDialog {
    Q_OBJECT
public:
    // `inputs`: (n, current value) of each IBn, in order.
    OperatorInputDialog(const std::vector<std::pair<int, double>>& inputs, QWidget* parent);

    // (n, value) of each field; the fields hold numbers only.
    std::vector<std::pair<int, double>> values() const;
    QLineEdit* field(int n) const;

private:
    std::vector<std::pair<int, QLineEdit*>> m_fields;
};

}  // namespace kerf::ui
