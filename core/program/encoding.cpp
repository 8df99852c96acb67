#include "core/program/encoding.h"

#include <cerrno>
#include <cstdint>
#include <cstring>

#include <iconv.h>

namespace kerf::program {

namespace {

const char* iconvName(Encoding encoding) {
    switch (encoding) {
        case Encoding::Cp1252:
            return "CP1252";
        case Encoding::Gbk:
            return "GBK";
        case Encoding::Utf16Le:
            return "UTF-16LE";
        case Encoding::Utf16Be:
            return "UTF-16BE";
        case Encoding::Utf8:
            break;
    }
    return "UTF-8";
}

std::string_view byteOrderMark(Encoding encoding) {
    if (encoding == Encoding::Utf16Le) return "\xFF\xFE";
    if (encoding == Encoding::Utf16Be) return "\xFE\xFF";
    return {};
}

// Runs iconv over the whole input; an unconvertible byte sequence is replaced by `replacement` and
// conversion resumes one byte later.
std::string convert(std::string_view input, const char* to, const char* from,
                    std::string_view replacement, bool skipContinuation) {
    iconv_t cd = ::iconv_open(to, from);
    if (cd == reinterpret_cast<iconv_t>(-1)) return std::string(input);
    std::string out;
    out.resize(input.size() * 4 + 16);
    char* in = const_cast<char*>(input.data());
    size_t inLeft = input.size();
    char* outPtr = out.data();
    size_t outLeft = out.size();
    while (inLeft > 0) {
        size_t result = ::iconv(cd, &in, &inLeft, &outPtr, &outLeft);
        if (result != static_cast<size_t>(-1)) break;
        if (errno == E2BIG) {
            size_t used = static_cast<size_t>(outPtr - out.data());
            out.resize(out.size() * 2);
            outPtr = out.data() + used;
            outLeft = out.size() - used;
            continue;
        }
        // EILSEQ or EINVAL: skip one byte and write the replacement.
        if (outLeft < replacement.size()) {
            size_t used = static_cast<size_t>(outPtr - out.data());
            out.resize(out.size() * 2 + replacement.size());
            outPtr = out.data() + used;
            outLeft = out.size() - used;
        }
        for (char c : replacement)
            *outPtr++ = c;
        outLeft -= replacement.size();
        ++in;
        --inLeft;
        // From UTF-8, drop the rest of the character too.
        while (skipContinuation && inLeft > 0 && (static_cast<unsigned char>(*in) & 0xC0) == 0x80) {
            ++in;
            --inLeft;
        }
        ::iconv(cd, nullptr, nullptr, nullptr, nullptr);
    }
    out.resize(static_cast<size_t>(outPtr - out.data()));
    ::iconv_close(cd);
    return out;
}

}  // namespace

const char* encodingName(Encoding encoding) {
    switch (encoding) {
        case Encoding::Cp1252:
            return "cp1252";
        case Encoding::Gbk:
            return "gbk";
        case Encoding::Utf16Le:
            return "utf-16le";
        case Encoding::Utf16Be:
            return "utf-16be";
        case Encoding::Utf8:
            break;
    }
    return "utf-8";
}

bool isValidUtf8(std::string_view bytes) {
    size_t i = 0;
    const size_t n = bytes.size();
    while (i < n) {
        // Skip plain ASCII eight bytes at a time.
        while (i + 8 <= n) {
            uint64_t word;
            std::memcpy(&word, bytes.data() + i, 8);
            if ((word & 0x8080808080808080ull) != 0) break;
            i += 8;
        }
        if (i >= n) break;
        auto c = static_cast<unsigned char>(bytes[i]);
        if (c < 0x80) {
            ++i;
            continue;
        }
        size_t extra;
        unsigned minimum;
        unsigned codePoint;
        if ((c & 0xE0) == 0xC0) {
            extra = 1;
            minimum = 0x80;
            codePoint = c & 0x1Fu;
        } else if ((c & 0xF0) == 0xE0) {
            extra = 2;
            minimum = 0x800;
            codePoint = c & 0x0Fu;
        } else if ((c & 0xF8) == 0xF0) {
            extra = 3;
            minimum = 0x10000;
            codePoint = c & 0x07u;
        } else {
            return false;
        }
        for (size_t k = 1; k <= extra; ++k) {
            if (i + k >= n) return false;
            auto d = static_cast<unsigned char>(bytes[i + k]);
            if ((d & 0xC0) != 0x80) return false;
            codePoint = (codePoint << 6) | (d & 0x3Fu);
        }
        if (codePoint < minimum || codePoint > 0x10FFFF ||
            (codePoint >= 0xD800 && codePoint <= 0xDFFF)) {
            return false;
        }
        i += extra + 1;
    }
    return true;
}

Encoding detectEncoding(std::string_view bytes) {
    if (bytes.starts_with(byteOrderMark(Encoding::Utf16Le))) return Encoding::Utf16Le;
    if (bytes.starts_with(byteOrderMark(Encoding::Utf16Be))) return Encoding::Utf16Be;
    if (isValidUtf8(bytes)) return Encoding::Utf8;
    size_t pairedHigh = 0;
    size_t isolatedHigh = 0;
    for (size_t i = 0; i < bytes.size(); ++i) {
        auto c = static_cast<unsigned char>(bytes[i]);
        if (c < 0x81) continue;
        if (i + 1 < bytes.size() && static_cast<unsigned char>(bytes[i + 1]) >= 0x80) {
            ++pairedHigh;
            ++i;
        } else {
            ++isolatedHigh;
        }
    }
    return pairedHigh > isolatedHigh ? Encoding::Gbk : Encoding::Cp1252;
}

std::string toUtf8(std::string_view bytes, Encoding encoding) {
    if (encoding == Encoding::Utf8) return std::string(bytes);
    const std::string_view mark = byteOrderMark(encoding);
    if (!mark.empty() && bytes.starts_with(mark)) bytes.remove_prefix(mark.size());
    return convert(bytes, "UTF-8", iconvName(encoding), "\xEF\xBF\xBD", false);
}

std::string fromUtf8(std::string_view text, Encoding encoding) {
    if (encoding == Encoding::Utf8) return std::string(text);
    return std::string(byteOrderMark(encoding)) +
           convert(text, iconvName(encoding), "UTF-8", "?", true);
}

}  // namespace kerf::program
