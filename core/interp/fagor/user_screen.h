#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace kerf::fagor {

// The operating mode whose user customisation program runs (machine parameters USERDPLY,
// USEREDIT, USERMAN, USERDIAG; spec part 2 §6.8).
enum class UserMode : uint8_t { Execution, Edit, Manual, Diagnosis };

// The format of an IB input: "-" allows negative values; at most `integerDigits` (0-6) and
// `decimals` (0-5) digits.
struct InputFormat {
    bool negative = false;
    int integerDigits = 6;
    int decimals = 5;
};

// A data window of ODW: 1 row x 14 columns at a text row (0-20) and column (0-79).
struct DataWindow {
    int row = 0;
    int column = 0;
    std::string text;  // what DW shows in it
};

// A user symbol SYMBOL drew at a pixel column (0-639) and row (0-335).
struct ScreenSymbol {
    int number = 0;
    int column = 0;
    int row = 0;
};

// The user screen of the FAGOR 8035 user channel: what a customisation program shows (page,
// symbols, data windows, softkeys, the input prompt) and what the operator gives back (keys for
// WKEY, numbers for IB). Qt-free: the interpreter drives it, a panel draws it, the headless run
// prints it. Used from one thread.
class UserScreen {
public:
    static constexpr int kWindows = 26;
    static constexpr int kSoftkeys = 7;
    static constexpr int kInputs = 26;
    static constexpr int kSoftkeyF1 = 0xFC00;  // F1; F2-F7 follow (spec part 2 §8.D)

    explicit UserScreen(UserMode mode = UserMode::Execution) : m_mode(mode) {}

    UserMode mode() const { return m_mode; }

    // ---- what the customisation program does ----
    // A new page replaces the screen: windows and symbols of the previous page are gone.
    void showPage(int page);
    void drawSymbol(const ScreenSymbol& symbol);
    void defineWindow(int window, int row, int column);
    // False when the window was not defined by ODW.
    bool showInWindow(int window, std::string text);
    // SK: over the standard menu the named softkeys replace all; over a user menu only those named.
    void setSoftkeys(const std::vector<std::pair<int, std::string>>& keys);
    // IB without a format: the text is shown and nothing is asked.
    void showPrompt(std::string text);
    // IB with a format: asks the operator for IB`input`.
    void askNumber(int input, std::string prompt, InputFormat format);
    void askKey();  // WKEY
    // The operator's answer to askNumber (stored in its IB variable) or a key pressed; nullopt
    // while there is none.
    std::optional<double> takeNumber();
    std::optional<int> takeKey();
    void appendToBlock(std::string_view text);  // WBUF "text", value
    void insertBlock();                         // WBUF: the block goes into the edited program
    void leave();                               // SYSTEM
    void setKeySource(int source) { m_keySource = source; }

    // ---- the operator ----
    enum class Waiting : uint8_t { Nothing, Key, Number };
    Waiting waiting() const { return m_waiting; }
    // The key for the WKEY that waits; false when none waits or keys come from the PLC or DNC
    // (KEYSRC), not the keyboard.
    bool pressKey(int code);
    // The typed number for the pending IB; an English message template when it does not fit the
    // format (nothing is stored then).
    std::optional<std::string> enterNumber(std::string_view text);
    // Blocks WBUF inserted since the last call, in order (the panel puts them after the cursor).
    std::vector<std::string> takeInsertedBlocks();

    // ---- what the panel draws ----
    int page() const { return m_page; }  // -1: none yet
    const std::vector<ScreenSymbol>& symbols() const { return m_symbols; }
    const std::array<std::optional<DataWindow>, kWindows>& windows() const { return m_windows; }
    const std::array<std::string, kSoftkeys>& softkeys() const { return m_softkeys; }
    bool userMenu() const { return m_userMenu; }
    const std::string& prompt() const { return m_prompt; }
    const InputFormat& format() const { return m_format; }
    int pendingInput() const { return m_input; }  // the IB asked for
    const std::string& editBuffer() const { return m_editBuffer; }
    const std::vector<std::string>& insertedBlocks() const { return m_inserted; }
    double input(int n) const { return m_inputs[static_cast<size_t>(n)]; }
    const std::array<double, kInputs>& inputs() const { return m_inputs; }
    int keySource() const { return m_keySource; }
    bool left() const { return m_left; }
    // Grows with every change, so that a view repaints only when needed.
    uint64_t revision() const { return m_revision; }

    // The screen as text, for the headless run and tests.
    std::string describe() const;

private:
    UserMode m_mode;
    int m_page = -1;
    std::vector<ScreenSymbol> m_symbols;
    std::array<std::optional<DataWindow>, kWindows> m_windows{};
    std::array<std::string, kSoftkeys> m_softkeys{};
    bool m_userMenu = false;
    std::string m_prompt;
    InputFormat m_format;
    int m_input = -1;
    Waiting m_waiting = Waiting::Nothing;
    std::optional<int> m_key;
    std::optional<double> m_answer;
    std::array<double, kInputs> m_inputs{};
    std::string m_editBuffer;
    std::vector<std::string> m_inserted;
    size_t m_insertedTaken = 0;
    int m_keySource = 0;
    bool m_left = false;
    uint64_t m_revision = 0;
};

// How DW, DWH and DWB show a value: "100", "64", "01100100" (spec part 2 §6.8).
std::string decimalText(double value);
std::string hexadecimalText(double value);
std::string binaryText(double value);
// A softkey text as its two lines of 10 characters (shorter than 10: centred on the upper one).
std::pair<std::string, std::string> softkeyLines(std::string_view text);
// The name of a key code: "F1".."F7" for the softkeys, the character for printable ASCII codes,
// else "$FC10" style.
std::string keyName(int code);
// The code of a key name ("F1", "$FC00", "65", one printable character); nullopt if none.
std::optional<int> keyCode(std::string_view name);

}  // namespace kerf::fagor
