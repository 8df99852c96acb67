#include "core/interp/klartext/q_parameters.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/base/atomic_file.h"

namespace kerf::klartext {

int qLimit(QKind kind) {
    switch (kind) {
        case QKind::QL:
            return kQlCount;
        case QKind::QR:
            return kQrCount;
        case QKind::QS:
            return kQsCount;
        case QKind::Q:
            break;
    }
    return kQCount;
}

const char* qPrefix(QKind kind) {
    switch (kind) {
        case QKind::QL:
            return "QL";
        case QKind::QR:
            return "QR";
        case QKind::QS:
            return "QS";
        case QKind::Q:
            break;
    }
    return "Q";
}

QParameters::QParameters()
    : m_q(kQCount, 0.0),
      m_local(1),
      m_localSet(1),
      m_strings(kQsCount),
      m_stringSet(kQsCount, false) {
    m_local.back().fill(0.0);
}

double QParameters::get(QRef ref) const {
    switch (ref.kind) {
        case QKind::QL:
            return m_local.back()[ref.index];
        case QKind::QR:
            return m_remanent[ref.index];
        case QKind::QS:
            return 0.0;
        case QKind::Q:
            break;
    }
    return m_q[ref.index];
}

void QParameters::set(QRef ref, double value) {
    switch (ref.kind) {
        case QKind::QL:
            m_local.back()[ref.index] = value;
            m_localSet.back().set(ref.index);
            return;
        case QKind::QR:
            if (m_remanent[ref.index] != value) m_remanentChanged = true;
            m_remanent[ref.index] = value;
            m_remanentSet.set(ref.index);
            return;
        case QKind::QS:
            return;
        case QKind::Q:
            break;
    }
    m_q[ref.index] = value;
    m_qSet.set(ref.index);
}

bool QParameters::isSet(QRef ref) const {
    switch (ref.kind) {
        case QKind::QL:
            return m_localSet.back().test(ref.index);
        case QKind::QR:
            return m_remanentSet.test(ref.index);
        case QKind::QS:
            return m_stringSet[ref.index];
        case QKind::Q:
            break;
    }
    return m_qSet.test(ref.index);
}

void QParameters::setString(uint16_t index, std::string value) {
    m_strings[index] = std::move(value);
    m_stringSet[index] = true;
}

void QParameters::pushLocalLevel() {
    m_local.emplace_back();
    m_local.back().fill(0.0);
    m_localSet.emplace_back();
}

void QParameters::popLocalLevel() {
    if (m_local.size() > 1) {
        m_local.pop_back();
        m_localSet.pop_back();
    }
}

MaybeError QParameters::loadRemanent(const std::filesystem::path& file) {
    std::error_code ignored;
    if (!std::filesystem::exists(file, ignored)) return std::nullopt;
    auto text = readWholeFile(file);
    if (!text) return text.error();
    size_t start = 0;
    uint32_t lineNumber = 0;
    while (start < text->size()) {
        size_t end = text->find('\n', start);
        if (end == std::string::npos) end = text->size();
        std::string_view line(text->data() + start, end - start);
        ++lineNumber;
        start = end + 1;
        if (line.empty()) continue;
        unsigned index = 0;
        double value = 0.0;
        size_t eq = line.find('=');
        bool ok = line.substr(0, 2) == "QR" && eq != std::string_view::npos;
        if (ok) {
            const char* lineEnd = line.data() + line.size();
            auto r1 = std::from_chars(line.data() + 2, line.data() + eq, index);
            auto r2 = std::from_chars(line.data() + eq + 1, lineEnd, value);
            ok = r1.ec == std::errc() && r1.ptr == line.data() + eq && index < kQrCount;
            // The whole rest is one finite number: "nan", "inf" or "5xyz" is a damaged file,
            // not a value (saveRemanent writes only finite numbers).
            if (ok && (r2.ec != std::errc() || r2.ptr != lineEnd || !std::isfinite(value))) {
                return Diagnostic::make(Severity::Error, "qr-file", file.string(), lineNumber,
                                        static_cast<uint32_t>(eq + 2),
                                        KERF_TR_NOOP("QR{1} = '{2}' is not a finite number"),
                                        std::to_string(index), std::string(line.substr(eq + 1)));
            }
        }
        if (!ok) {
            return Diagnostic::make(Severity::Error, "qr-file", file.string(), lineNumber, 1,
                                    KERF_TR_NOOP("expected QRn=value"));
        }
        m_remanent[index] = value;
        m_remanentSet.set(index);
    }
    m_remanentChanged = false;
    return std::nullopt;
}

MaybeError QParameters::saveRemanent(const std::filesystem::path& file) const {
    std::string text;
    char buffer[64];
    for (size_t i = 0; i < m_remanent.size(); ++i) {
        if (m_remanent[i] == 0.0) continue;
        int n = std::snprintf(buffer, sizeof buffer, "QR%zu=%.17g\n", i, m_remanent[i]);
        text.append(buffer, static_cast<size_t>(n));
    }
    return writeFileAtomically(file, text);
}

}  // namespace kerf::klartext
