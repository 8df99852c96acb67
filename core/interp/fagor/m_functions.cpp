#include "core/interp/fagor/m_functions.h"

namespace kerf::fagor {

std::vector<MFunctionEntry> defaultMFunctionTable() {
    std::vector<MFunctionEntry> table;
    for (int m : {0, 1, 2, 5, 6, 19, 30})
        table.push_back({m, 0, false, false, false});
    for (int m : {3, 4, 41, 42, 43, 44})
        table.push_back({m, 0, true, false, false});
    return table;
}

const MFunctionEntry* findMFunction(const std::vector<MFunctionEntry>& table, int number) {
    for (const MFunctionEntry& e : table) {
        if (e.number == number) return &e;
    }
    return nullptr;
}

}  // namespace kerf::fagor
