#pragma once

#include <QMetaType>
#include <cstdint>

namespace kerf::ui {

// Why a message stands. A message with a cause leaves the message line as soon as the cause is
// gone, as a TNC clears an error when its cause is removed; one without (an event: a refused
// save, a finished program) stays until it is cleared with CE or Clear messages.
enum class MessageCause : uint8_t {
    None,
    NotReferenced,   // an axis is not referenced yet
    EmergencyStop,   // the emergency stop button is pressed
    MachineOff,      // the drives are off (emergency stop, drive fault)
    Busy,            // a program, an MDI block, a jog or a reference run moves the machine
    ProgramRefused,  // the last NC start was refused (its program's errors): until one starts
    Moment,          // an information on the key just pressed (Machine on when it is on): a
                     // few seconds, as nothing the operator could remove causes it
};

}  // namespace kerf::ui

Q_DECLARE_METATYPE(kerf::ui::MessageCause)
