// The screen customisation instructions of the user channel: PAGE, SYMBOL, IB, ODW, DW, SK,
// WKEY, WBUF and SYSTEM (spec part 2 §6.8) drive the UserScreen of the settings.
#include "core/base/translate.h"
#include "core/interp/fagor/fagor_interpreter.h"

namespace kerf::fagor {

void FagorInterpreter::waitForOperator() {
    emit(canon::SyncPoint{canon::SyncReason::Operator});
    m_resumeBlock = true;
    m_syncedThisBlock = true;
    m_askedOperator = true;
    m_status = interp::RunStatus::NeedsSync;
}

bool FagorInterpreter::screen(const ScreenStatement& st, Problem& problem) {
    using Kind = ScreenStatement::Kind;
    UserScreen* screen = m_settings.userScreen;
    if (screen == nullptr) {
        return problemOf(problem, "not-supported",
                         KERF_TR_NOOP("screen customisation instructions run only in a user "
                                      "customisation program (the user screen)"));
    }
    // The block runs again after the operator answered (or resume() came without an answer).
    const bool asked = m_askedOperator;
    m_askedOperator = false;
    switch (st.kind) {
        case Kind::Page:
            screen->showPage(st.numbers[0]);
            return true;
        case Kind::Symbol:
            screen->drawSymbol(ScreenSymbol{st.numbers[0], st.numbers[1], st.numbers[2]});
            return true;
        case Kind::DefineWindow:
            screen->defineWindow(st.numbers[0], st.numbers[1], st.numbers[2]);
            return true;
        case Kind::ShowData:
            for (const ScreenStatement::WindowData& w : st.windows) {
                if (!screen->showInWindow(w.window, w.text)) {
                    return problemOf(problem, "screen",
                                     KERF_TR_NOOP("data window {1} is not defined (ODW)"),
                                     {std::to_string(w.window)});
                }
            }
            return true;
        case Kind::Softkeys:
            screen->setSoftkeys(st.softkeys);
            return true;
        case Kind::Input:
            if (!st.format) {
                // Without a format the text is shown and the program goes on.
                screen->showPrompt(st.text);
                return true;
            }
            if (asked && screen->takeNumber()) return true;
            if (!asked) screen->askNumber(st.index, st.text, *st.format);
            waitForOperator();
            return true;
        case Kind::WaitKey:
            if (screen->keySource() != 0) {
                return problemOf(problem, "not-available",
                                 KERF_TR_NOOP("WKEY: keys come from the PLC or DNC (KEYSRC), "
                                              "which this control does not have"));
            }
            if (asked) {
                if (const auto key = screen->takeKey()) {
                    m_key = *key;
                    return true;
                }
            } else {
                screen->askKey();
            }
            waitForOperator();
            return true;
        case Kind::AppendToBlock:
        case Kind::InsertBlock:
            if (screen->mode() != UserMode::Edit) {
                return problemOf(problem, "screen",
                                 KERF_TR_NOOP("WBUF runs only in the customisation program of "
                                              "the edit mode (USEREDIT)"));
            }
            if (st.kind == Kind::InsertBlock) {
                screen->insertBlock();
            } else {
                screen->appendToBlock(st.value ? st.text + decimalText(*st.value) : st.text);
            }
            return true;
        case Kind::System:
            screen->leave();
            finish(-1);
            m_jumped = true;
            return true;
    }
    return true;
}

}  // namespace kerf::fagor
