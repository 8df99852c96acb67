#pragma once

#include <QDialog>
#include <QStringList>

class QComboBox;
class QPushButton;

namespace kerf::ui {

// Positioning with MDI: a field for the block, with the blocks run before in this session in
// its list (the latest first; the arrow keys or the list pick one to run again).
class MdiDialog : public QDialog {
    Q_OBJECT

public:
    explicit MdiDialog(const QStringList& history, QWidget* parent = nullptr);

    QString block() const;
    QComboBox* blockField() const { return m_block; }
    QPushButton* okButton() const { return m_ok; }
    QPushButton* cancelButton() const { return m_cancel; }

private:
    QComboBox* m_block = nullptr;
    QPushButton* m_ok = nullptr;
    QPushButton* m_cancel = nullptr;
};

}  // namespace kerf::ui
