#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/interp/tnciso/iso_translator.h"

namespace kerf::tnciso {

// The block being translated, shared by iso_translator.cpp and iso_translator_cycles.cpp.
struct IsoTranslator::Context {
    const program::LogicalLine& line;
    std::string_view text;
    Translation& out;
    const IsoWords& words;
    std::vector<bool>& used;

    ConversationalBlock& newBlock() { return out.newBlock(); }
    const IsoWord* take(std::string_view key) {
        if (key[0] >= 'A' && key[0] <= 'Z' && !words.hasLetter(key[0])) return nullptr;
        for (size_t i = 0; i < words.words.size(); ++i) {
            if (!used[i] && words.words[i].key == key) {
                used[i] = true;
                return &words.words[i];
            }
        }
        return nullptr;
    }
    bool has(std::string_view key) const { return words.find(key) != nullptr; }
    size_t end(const IsoWord& w) const {
        return w.value.empty() ? w.offset + w.key.size() : w.valueOffset + w.value.size();
    }
    // "X+10" as written, with an "I" before it for incremental dimensions.
    void addWord(ConversationalBlock& b, const IsoWord& w, std::string_view key,
                 bool incremental = false) {
        std::string head;
        if (incremental) head.push_back('I');
        head.append(key);
        b.add(head, w.offset, w.valueOffset - w.offset, true);
        b.add(w.value, w.valueOffset, w.value.size());
    }
    void addFeedAndM(ConversationalBlock& b) {
        for (const char* key : {"F", "FU", "FZ"}) {
            if (const IsoWord* f = take(key)) addWord(b, *f, key);
        }
        if (const IsoWord* f = take("FMAX")) b.add("FMAX", f->offset, 4);
        if (const IsoWord* f = take("FAUTO")) b.add("FAUTO", f->offset, 5);
        addM(b);
    }
    void addM(ConversationalBlock& b) {
        while (const IsoWord* m = take("M")) {
            b.add("M" + std::to_string(m->number), m->offset, end(*m) - m->offset);
        }
    }
};

}  // namespace kerf::tnciso
