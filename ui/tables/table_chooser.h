#pragma once

#include <QWidget>
#include <filesystem>
#include <vector>

#include "ui/tables/table_kinds.h"

class QLabel;
class QPushButton;

namespace kerf::ui {

// The "Tables" page: one large button per table the machine has (the TNC tables on a mill, the
// FAGOR tables on a lathe), each naming the table, its file in the NC root and what it holds.
// Choosing one asks for the file to be opened in the table editor.
class TableChooser : public QWidget {
    Q_OBJECT

public:
    TableChooser(std::filesystem::path ncRoot, bool lathe, QWidget* parent = nullptr);

    const std::vector<TableKind>& kinds() const { return m_kinds; }
    std::filesystem::path pathOf(TableKind kind) const;
    void choose(TableKind kind);

    // Short name for a softkey ("Datum\ntable") and a one-line description.
    static QString kindName(TableKind kind);
    static QString kindDescription(TableKind kind);

signals:
    void openRequested(const std::filesystem::path& path);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();

    std::filesystem::path m_ncRoot;
    std::vector<TableKind> m_kinds;
    QLabel* m_title = nullptr;
    std::vector<QPushButton*> m_buttons;
};

}  // namespace kerf::ui
