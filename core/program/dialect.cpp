#include "core/program/dialect.h"

namespace kerf::program {

const char* dialectName(Dialect dialect) {
    switch (dialect) {
        case Dialect::TncIso:
            return "tnciso";
        case Dialect::Fagor:
            return "fagor";
        case Dialect::Klartext:
            break;
    }
    return "klartext";
}

std::optional<Dialect> dialectFromName(std::string_view name) {
    if (name == "klartext" || name == "conversational" || name == "heidenhain") {
        return Dialect::Klartext;
    }
    if (name == "tnciso" || name == "iso") return Dialect::TncIso;
    if (name == "fagor") return Dialect::Fagor;
    return std::nullopt;
}

Dialect dialectForFile(std::string_view path, bool latheMachine) {
    size_t dot = path.find_last_of('.');
    size_t slash = path.find_last_of('/');
    if (dot != std::string_view::npos && (slash == std::string_view::npos || dot > slash)) {
        std::string_view ext = path.substr(dot + 1);
        if (ext == "H" || ext == "h") return Dialect::Klartext;
        if (ext == "I" || ext == "i") return Dialect::TncIso;
    }
    return latheMachine ? Dialect::Fagor : Dialect::Klartext;
}

}  // namespace kerf::program
