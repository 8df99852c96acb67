// FN functions that talk to the machine state, files and tables: FN 14, 15, 16, 18, 23, 24,
// 26, 27, 28.
#include <cmath>
#include <ctime>

#include <Eigen/Dense>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/interp/klartext/fn14_errors.h"
#include "core/interp/klartext/fprint_formatter.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/interp/klartext/spatial_angles.h"

namespace kerf::klartext {

void KlartextInterpreter::executeError(const ErrorBlock& block) {
    const char* text = fn14ErrorText(block.number);
    std::string message = text ? text : "";
    emit(canon::Message{canon::MessageKind::Error, std::to_string(block.number) + " " + message});
    if (text) {
        fail("fn14", KERF_TR_NOOP("FN 14 error {1}: {2}"), {std::to_string(block.number), text});
    } else {
        fail("fn14", KERF_TR_NOOP("FN 14 error {1}"), {std::to_string(block.number)});
    }
}

void KlartextInterpreter::executePrint(const PrintBlock& print) {
    if (!print.formatted) {
        std::string text = print.text;
        for (size_t i = 0; i < print.values.size(); ++i) {
            if (i > 0) text += "  ";
            appendFixed(text, print.values[i], 4);
        }
        emit(canon::Message{canon::MessageKind::Print, text});
        return;
    }
    const std::filesystem::path folder = m_levels.back().program->folder;
    auto maskPath = m_root.resolve(print.maskFile, folder);
    auto outputPath = m_root.resolve(print.outputFile, folder);
    if (!maskPath || !outputPath) {
        const Diagnostic& e = maskPath ? outputPath.error() : maskPath.error();
        fail("path", e.messageTemplate.c_str(), e.args);
        return;
    }
    auto mask = m_root.read(*maskPath);
    if (!mask) {
        fail("io", KERF_TR_NOOP("cannot read the F-PRINT mask {1}"), {print.maskFile});
        return;
    }
    std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    auto formatted = formatFPrint(*mask, maskPath->string(), *m_environment, local);
    if (!formatted) {
        appendDiagnostic(m_diagnostics, formatted.error());
        fail("fprint", KERF_TR_NOOP("F-PRINT mask {1} has an error"), {print.maskFile});
        return;
    }
    // No file changes before the whole program has passed its check.
    if (!waitForCheck()) return;
    std::string content = formatted->text;
    std::error_code ignored;
    if (formatted->append && std::filesystem::exists(*outputPath, ignored)) {
        auto previous = m_root.read(*outputPath);
        if (previous) content = *previous + content;
    }
    if (auto error = replaceFile(*outputPath, content)) {
        appendDiagnostic(m_diagnostics, *error);
        fail("io", KERF_TR_NOOP("cannot write {1}"), {print.outputFile});
    }
}

std::optional<double> KlartextInterpreter::sysReadValue(const SysRead& read, bool& needsSync) {
    needsSync = false;
    const double scale = lengthScale();
    const int axisIndexValue = read.idx - 1;
    const bool validAxis = axisIndexValue >= 0 && axisIndexValue < kAxisCount;
    switch (read.id) {
        case 20:  // machine status
            switch (read.nr) {
                case 1:
                    return m_tool.number;
                case 2:
                    return m_preparedTool;
                case 3:
                    return m_toolAxis == Axis::X ? 0.0 : (m_toolAxis == Axis::Y ? 1.0 : 2.0);
                case 4:
                    return m_spindleSpeed;
                case 5:
                    if (m_spindle == canon::SpindleDirection::Clockwise) return 0.0;
                    if (m_spindle == canon::SpindleDirection::CounterClockwise) return 1.0;
                    if (m_lastSpindleDirection == canon::SpindleDirection::Clockwise) return 2.0;
                    if (m_lastSpindleDirection == canon::SpindleDirection::CounterClockwise)
                        return 3.0;
                    return -1.0;
                case 8:
                    return m_coolant ? 1.0 : 0.0;
                case 9:
                    return m_feed / scale;
                default:
                    break;
            }
            break;
        case 50: {  // tool table data of tool IDX (the active tool without IDX)
            const tables::ToolData* data = nullptr;
            tables::ToolData active;
            int number = read.hasIdx ? read.idx : m_tool.number;
            if (number == m_tool.number || !toolTable()) {
                active.length = m_tool.length;
                active.radius = m_tool.radius;
                active.radius2 = m_tool.radius2;
                active.deltaLength = m_tool.tableDl;
                active.deltaRadius = m_tool.tableDr;
                active.deltaRadius2 = m_tool.tableDr2;
                data = &active;
            } else {
                data = toolTable()->byNumber(number);
            }
            if (data == nullptr) return std::nullopt;
            switch (read.nr) {
                case 1:
                    return data->length / scale;
                case 2:
                    return data->radius / scale;
                case 3:
                    return data->radius2 / scale;
                case 4:
                    return data->deltaLength / scale;
                case 5:
                    return data->deltaRadius / scale;
                case 6:
                    return data->deltaRadius2 / scale;
                case 7:
                    return data->locked ? 1.0 : 0.0;
                default:
                    break;
            }
            break;
        }
        case 210:  // active transformations
            switch (read.nr) {
                case 1:  // basic rotation (manual operation): none in this release
                    return 0.0;
                case 5:  // 3D ROT: the tilted plane's spatial angles A, B, C (IDX 1-3)
                    if (read.idx >= 1 && read.idx <= 3) {
                        if (!m_tilt.active) return 0.0;
                        return spatialAnglesOf(m_tilt.rotation)[static_cast<size_t>(read.idx - 1)];
                    }
                    break;
                case 6:  // tilted working plane in the program run: -1 active, 0 not
                    return m_tilt.active ? -1.0 : 0.0;
                case 7:  // tilted working plane of manual operation: Kerf has none
                    return 0.0;
                case 2:
                    return m_frame.rotationDeg();
                case 3:  // mirrored axes, bit 0 = X, bit 1 = Y, ...
                    return static_cast<double>(m_frame.mirror());
                case 4:
                    return m_frame.scale();
                default:
                    break;
            }
            break;
        case 220:  // active datum shift (cycle 7)
            if (read.nr == 2 && validAxis) {
                return m_frame.shift().values[static_cast<size_t>(axisIndexValue)] / scale;
            }
            break;
        case 230:  // traverse range (software limits, machine coordinates)
            if ((read.nr == 2 || read.nr == 3) && validAxis && m_settings.machine) {
                const machine::AxisConfig* axis =
                    m_settings.machine->axis(axisLetter(static_cast<Axis>(axisIndexValue)));
                if (axis) return (read.nr == 2 ? axis->minLimit : axis->maxLimit) / scale;
            }
            break;
        case 280:  // M128 / FUNCTION TCPM: -1 active, 0 not
            if (read.nr == 1) return m_tcpm ? -1.0 : 0.0;
            break;
        case 240:  // nominal position in the machine (REF) system
        case 270:  // current position in the active coordinate system
            if (read.nr == 1 && validAxis) {
                needsSync = true;
                return 0.0;
            }
            break;
        default:
            break;
    }
    return std::nullopt;
}

void KlartextInterpreter::executeSysRead(const SysRead& read) {
    bool needsSync = false;
    auto value = sysReadValue(read, needsSync);
    if (!value) {
        fail("not-supported", KERF_TR_NOOP("FN 18: SYSREAD ID{1} NR{2} IDX{3} is not available"),
             {std::to_string(read.id), std::to_string(read.nr), std::to_string(read.idx)});
        return;
    }
    if (!needsSync) {
        m_q.set(read.target, *value);
        return;
    }
    // Positions come from the machine: let motion finish first.
    if (!checkPathError(m_path.flush())) return;
    emit(canon::SyncPoint{canon::SyncReason::ReadPosition});
    m_pendingSync = PendingSync{read.target, read.id, read.nr, read.idx};
    m_status = interp::RunStatus::NeedsSync;
}

void KlartextInterpreter::waitForSync() {
    if (!checkPathError(m_path.flush())) return;
    emit(canon::SyncPoint{canon::SyncReason::ReadPosition});
    m_pendingSync = PendingSync{};
    m_status = interp::RunStatus::NeedsSync;
}

void KlartextInterpreter::executeCircleData(const CircleData& data) {
    auto point = [&](int i) {
        QRef x = data.source, y = data.source;
        x.index = static_cast<uint16_t>(data.source.index + 2 * i);
        y.index = static_cast<uint16_t>(data.source.index + 2 * i + 1);
        return Vec2(m_q.get(x), m_q.get(y));
    };
    std::optional<Circle> circle;
    if (data.points == 3) {
        circle = circleThrough(point(0), point(1), point(2));
    } else {
        // Four points: the least-squares circle (exact when they lie on one circle).
        double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0, sz = 0, sxz = 0, syz = 0;
        for (int i = 0; i < 4; ++i) {
            Vec2 p = point(i);
            double z = p.squaredNorm();
            sx += p.x();
            sy += p.y();
            sxx += p.x() * p.x();
            syy += p.y() * p.y();
            sxy += p.x() * p.y();
            sz += z;
            sxz += p.x() * z;
            syz += p.y() * z;
        }
        Eigen::Matrix3d a;
        a << sxx, sxy, sx, sxy, syy, sy, sx, sy, 4.0;
        Eigen::Vector3d b(sxz, syz, sz);
        if (std::fabs(a.determinant()) > 1e-12) {
            Eigen::Vector3d s = a.colPivHouseholderQr().solve(b);
            Vec2 center(s[0] / 2.0, s[1] / 2.0);
            double r2 = s[2] + center.squaredNorm();
            if (r2 > 0.0) circle = Circle{center, std::sqrt(r2)};
        }
    }
    if (!circle) {
        fail("math", KERF_TR_NOOP("FN {1}: the points do not define a circle"),
             {std::to_string(data.points == 3 ? 23 : 24)});
        return;
    }
    QRef out = data.target;
    m_q.set(out, circle->center.x());
    out.index = static_cast<uint16_t>(data.target.index + 1);
    m_q.set(out, circle->center.y());
    out.index = static_cast<uint16_t>(data.target.index + 2);
    m_q.set(out, circle->radius);
}

void KlartextInterpreter::executeTableOpen(const TableOpen& open) {
    auto path = m_root.resolve(open.path, m_levels.back().program->folder);
    if (!path) {
        fail("path", path.error().messageTemplate.c_str(), path.error().args);
        return;
    }
    auto bytes = m_root.read(*path);
    auto parsed = bytes ? tables::TncTable::parse(*bytes, path->string()) : bytes.error();
    auto table = parsed ? tables::FreeTable::fromTable(std::move(*parsed), *path) : parsed.error();
    if (!table) {
        appendDiagnostic(m_diagnostics, table.error());
        fail("table", KERF_TR_NOOP("FN 26: cannot open table {1}"), {open.path});
        return;
    }
    m_openTable.emplace(std::move(*table));
}

void KlartextInterpreter::executeTableAccess(const TableAccess& access) {
    if (!m_openTable) {
        fail("table", KERF_TR_NOOP("no table is open (FN 26: TABOPEN)"));
        return;
    }
    if (access.write) {
        // No file changes before the whole program has passed its check.
        if (!waitForCheck()) return;
        std::vector<double> values;
        for (size_t i = 0; i < access.columnCount; ++i) {
            QRef ref = access.parameter;
            ref.index = static_cast<uint16_t>(ref.index + i);
            values.push_back(m_q.get(ref));
        }
        auto error = m_openTable->write(access.row, access.columns, values);
        if (!error) error = replaceFile(m_openTable->path(), m_openTable->table().serialize());
        if (error) {
            appendDiagnostic(m_diagnostics, *error);
            fail("table", KERF_TR_NOOP("FN 27: cannot write row {1}"),
                 {std::to_string(access.row)});
        }
        return;
    }
    auto values = m_openTable->read(access.row, access.columns);
    if (!values) {
        appendDiagnostic(m_diagnostics, values.error());
        fail("table", KERF_TR_NOOP("FN 28: cannot read row {1}"), {std::to_string(access.row)});
        return;
    }
    for (size_t i = 0; i < values->size(); ++i) {
        QRef ref = access.parameter;
        ref.index = static_cast<uint16_t>(ref.index + i);
        m_q.set(ref, (*values)[i]);
    }
}

}  // namespace kerf::klartext
