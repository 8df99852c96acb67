#include "ui/userscreen/user_screen_run.h"

#include <QCoreApplication>

#include "core/canon/commands.h"
#include "core/program/nc_root.h"

namespace kerf::ui {

namespace {

// Blocks per tick: a display loop refreshes its windows about 10 000 times a second.
constexpr uint64_t kBlocksPerTick = 200;
constexpr int kTickMs = 20;

// The user channel moves no axis: what it emits (its end) is not needed.
class NoOutput final : public canon::Sink {
public:
    void consume(const canon::Command&) override {}
};

}  // namespace

UserScreenRun::UserScreenRun(const machine::MachineConfig& machine, QObject* parent)
    : QObject(parent), m_machine(machine) {
    m_timer.setInterval(kTickMs);
    connect(&m_timer, &QTimer::timeout, this, [this] { step(); });
}

UserScreenRun::~UserScreenRun() = default;

bool UserScreenRun::start(const std::filesystem::path& program, const std::filesystem::path& ncRoot,
                          fagor::UserMode mode) {
    stop();
    m_ncRoot = ncRoot;
    m_images.clear();
    m_screen = std::make_unique<fagor::UserScreen>(mode);
    task::ProgramRequest request;
    request.path = program;
    request.ncRoot = ncRoot;
    request.dialect = program::Dialect::Fagor;
    request.userScreen = m_screen.get();
    m_program = task::loadProgram(m_machine, request);
    m_diagnostics = m_program.diagnostics();
    m_revision = m_screen->revision();
    if (!m_program.ready) return false;
    m_timer.start();
    emit changed();
    return true;
}

const QImage* UserScreenRun::image(const std::string& fileName) const {
    auto [it, added] = m_images.try_emplace(fileName);
    if (added && !m_ncRoot.empty()) {
        // Through the NC root's file access: inside the root, regular files only.
        const program::NcRoot root(m_ncRoot);
        const Expected<std::string> bytes = root.read(m_ncRoot / fileName);
        QImage picture;
        if (bytes && picture.loadFromData(reinterpret_cast<const uchar*>(bytes->data()),
                                          static_cast<int>(bytes->size()), "PNG")) {
            it->second = std::move(picture);
        }
    }
    return it->second ? &*it->second : nullptr;
}

const QImage* UserScreenRun::pageImage(int page) const {
    return image("PAGE" + std::to_string(page) + ".PNG");
}

const QImage* UserScreenRun::symbolImage(int symbol) const {
    return image("SYMBOL" + std::to_string(symbol) + ".PNG");
}

void UserScreenRun::stop() {
    m_timer.stop();
    m_waitingForOperator = false;
    m_program.interpreter.reset();
}

bool UserScreenRun::waiting() const {
    return m_waitingForOperator && m_screen &&
           m_screen->waiting() != fagor::UserScreen::Waiting::Nothing;
}

void UserScreenRun::step() {
    if (!m_program.interpreter) return m_timer.stop();
    NoOutput output;
    interp::Interpreter& interpreter = *m_program.interpreter;
    const interp::RunStatus status = interpreter.run(output, kBlocksPerTick);
    bool ended = false;
    if (status == interp::RunStatus::NeedsSync) {
        if (m_screen->waiting() != fagor::UserScreen::Waiting::Nothing) {
            m_timer.stop();
            m_waitingForOperator = true;
        } else {
            // Another sync (a machine variable): the user channel does not move, go on.
            interpreter.resume(interp::WorldSnapshot{interpreter.nominalPosition(), false, {}});
        }
    } else if (status != interp::RunStatus::BudgetUsed) {
        m_timer.stop();
        m_diagnostics = m_program.diagnostics();
        ended = true;
    }
    // After the waiting state is known, so that the view shows what is asked for.
    if (m_screen->revision() != m_revision || m_waitingForOperator || ended) {
        m_revision = m_screen->revision();
        emit changed();
    }
    if (ended) emit this->ended(status == interp::RunStatus::Failed);
}

void UserScreenRun::resume() {
    m_waitingForOperator = false;
    m_program.interpreter->resume(
        interp::WorldSnapshot{m_program.interpreter->nominalPosition(), false, {}});
    m_timer.start();
    step();
}

bool UserScreenRun::pressKey(int code) {
    if (!waiting() || !m_screen->pressKey(code)) return false;
    resume();
    return true;
}

QString UserScreenRun::enterNumber(const QString& text) {
    if (!waiting()) return QCoreApplication::translate("kerf", "no input is asked for");
    if (const auto refused = m_screen->enterNumber(text.toStdString())) {
        return QCoreApplication::translate("kerf", refused->c_str());
    }
    resume();
    return {};
}

}  // namespace kerf::ui
