#pragma once

#include <QString>
#include <QWidget>
#include <functional>
#include <vector>

#include "ui/touch/touch_size.h"

class QPushButton;

namespace kerf::ui {

// One softkey: a stable id (for tests and scripting), its label and what it does.
struct Softkey {
    QString id;
    QString text;
    std::function<void()> action;
};

using SoftkeyRow = std::vector<Softkey>;

// The TNC softkey bar: eight keys under the screen, bound to F1..F8, and a ninth key that pages
// through further rows (F9). Each key is at least 48 px high so it can be hit with a finger.
class SoftkeyBar : public QWidget {
    Q_OBJECT

public:
    static constexpr int kKeys = 8;
    static constexpr int kMinimumKeyHeight = kTouchHeight;

    explicit SoftkeyBar(QWidget* parent = nullptr);

    // Replaces all rows (each at most kKeys keys; further keys are ignored) and shows the first.
    void setRows(std::vector<SoftkeyRow> rows);
    int rowCount() const { return static_cast<int>(m_rows.size()); }
    int currentRow() const { return m_current; }
    void showRow(int row);
    void nextRow();

    // Presses key `index` (0 = F1) of the current row; false if that key is empty.
    bool press(int index);
    // Presses the key with this id on whichever row holds it; false if there is none.
    bool pressId(const QString& id);
    QPushButton* keyButton(int index) const { return m_buttons.at(static_cast<size_t>(index)); }
    // The id of key `index` (0 = F1) of the current row, empty if there is none.
    QString keyId(int index) const;
    QPushButton* rowButton() const { return m_rowButton; }

signals:
    void pressed(const QString& id);

private:
    void refresh();

    std::vector<SoftkeyRow> m_rows;
    int m_current = 0;
    std::vector<QPushButton*> m_buttons;
    QPushButton* m_rowButton = nullptr;
};

}  // namespace kerf::ui
