#pragma once

#include <QImage>
#include <QObject>
#include <QString>
#include <QTimer>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "core/base/diagnostic.h"
#include "core/interp/fagor/user_screen.h"
#include "core/machine/machine_config.h"
#include "core/task/program_loader.h"

namespace kerf::ui {

// Runs a FAGOR user customisation program (spec part 2 §6.8) in the UI thread, a slice of blocks
// per timer tick, so that a display loop (EX-12.13) keeps the screen live without blocking it.
// While the program waits for the operator (WKEY, IB) the timer stops; a key or a number given
// here resumes it.
class UserScreenRun : public QObject {
    Q_OBJECT

public:
    explicit UserScreenRun(const machine::MachineConfig& machine, QObject* parent = nullptr);
    ~UserScreenRun() override;

    // Loads `program` as the customisation program of `mode` and starts it; false when it does
    // not pass its check (diagnostics() says why).
    bool start(const std::filesystem::path& program, const std::filesystem::path& ncRoot,
               fagor::UserMode mode);
    // The operator leaves the screen: the program stops where it is.
    void stop();
    bool running() const { return m_timer.isActive() || waiting(); }
    bool waiting() const;
    const fagor::UserScreen* screen() const { return m_screen.get(); }
    fagor::UserScreen* screen() { return m_screen.get(); }
    const DiagnosticList& diagnostics() const { return m_diagnostics; }

    // The drawings of the user pages and symbols. The control's customisation mode draws them
    // from the keyboard (operation manual, not in the spec); Kerf reads them as PNG images from
    // the NC root: PAGE<n>.PNG (n 0-255, 640 x 336 pixels) and SYMBOL<n>.PNG, drawn at their
    // pixel size. Null when the file is missing or no PNG image.
    const QImage* pageImage(int page) const;
    const QImage* symbolImage(int symbol) const;

    // The operator's key for WKEY; false when none is waited for.
    bool pressKey(int code);
    // The operator's number for IB; empty when accepted, else why not (translated).
    QString enterNumber(const QString& text);

signals:
    void changed();
    // The program ended (SYSTEM, its end) or failed (diagnostics()).
    void ended(bool failed);

private:
    void step();
    void resume();

    const machine::MachineConfig& m_machine;
    std::unique_ptr<fagor::UserScreen> m_screen;
    task::LoadedProgram m_program;
    DiagnosticList m_diagnostics;
    QTimer m_timer;
    uint64_t m_revision = 0;
    bool m_waitingForOperator = false;
    std::filesystem::path m_ncRoot;
    const QImage* image(const std::string& fileName) const;
    mutable std::map<std::string, std::optional<QImage>> m_images;  // by file name
};

}  // namespace kerf::ui
