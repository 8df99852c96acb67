// The tilted working plane (cycle 19 and PLANE) and the rotary axes: the plane's rotation, the
// rotary-axis angles that turn the tables to it (core/machine/table_kinematics.h), their
// positioning (MOVE, TURN, STAY) and the coordinate frame every following block runs in.
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/interp/klartext/spatial_angles.h"

namespace kerf::klartext {

namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
constexpr double kDegenerate = 1e-9;

// An enabled rotary axis that is not endless: only those have soft limits to keep.
bool hasLimitedRotaryAxis(const machine::MachineConfig& machine) {
    for (const machine::AxisConfig& axis : machine.axes) {
        if (axis.type == machine::AxisType::Rotary && !axis.endless && axis.enabled) return true;
    }
    return false;
}

using machine::principalRotation;

// The rotation whose columns are the tilted X, Y and Z axes: X along `x`, Z along `z`.
std::optional<Eigen::Matrix3d> frameOf(const Vec3& x, const Vec3& z) {
    if (z.norm() < kDegenerate) return std::nullopt;
    const Vec3 n = z.normalized();
    const Vec3 base = x - x.dot(n) * n;
    if (base.norm() < kDegenerate) return std::nullopt;
    Eigen::Matrix3d r;
    r.col(0) = base.normalized();
    r.col(2) = n;
    r.col(1) = n.cross(r.col(0));
    return r;
}

machine::SolutionChoice choiceOf(PlaneBlock::Sequence sequence) {
    switch (sequence) {
        case PlaneBlock::Sequence::Positive:
            return machine::SolutionChoice::PrimaryPositive;
        case PlaneBlock::Sequence::Negative:
            return machine::SolutionChoice::PrimaryNegative;
        default:
            return machine::SolutionChoice::Shortest;
    }
}

}  // namespace

std::optional<Eigen::Matrix3d> KlartextInterpreter::planeRotation(const PlaneBlock& b) {
    const auto& v = b.values;
    switch (b.kind) {
        case PlaneBlock::Kind::Spatial:
            return spatialRotation(v[0], v[1], v[2]);
        case PlaneBlock::Kind::Projected: {
            // PROPR and PROMIN: the angles of the plane's traces in the ZX and the YZ plane.
            const double p = v[0] / kDegPerRad, m = v[1] / kDegPerRad;
            const Vec3 u(std::cos(p), 0.0, -std::sin(p));
            const Vec3 w(0.0, std::cos(m), std::sin(m));
            auto r = frameOf(u, u.cross(w));
            if (r) return *r * principalRotation('C', v[2]);
            break;
        }
        case PlaneBlock::Kind::Euler:
            return principalRotation('C', v[0]) * principalRotation('A', v[1]) *
                   principalRotation('C', v[2]);
        case PlaneBlock::Kind::Vector: {
            auto r = frameOf(Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]));
            if (r) return r;
            break;
        }
        case PlaneBlock::Kind::Points: {
            const Vec3 p1(v[0], v[1], v[2]), p2(v[3], v[4], v[5]), p3(v[6], v[7], v[8]);
            auto r = frameOf(p2 - p1, (p2 - p1).cross(p3 - p1));
            if (r) return r;
            break;
        }
        case PlaneBlock::Kind::Relative:
            // About the axis of the active (tilted) system.
            return m_tilt.rotation * principalRotation("ABC"[b.relativeAxis], v[0]);
        case PlaneBlock::Kind::Axial:
        case PlaneBlock::Kind::Reset:
            return Eigen::Matrix3d::Identity();
    }
    fail("plane", KERF_TR_NOOP("PLANE: the points or vectors do not define a plane"));
    return std::nullopt;
}

machine::RotaryAngles KlartextInterpreter::currentTableAngles() const {
    machine::RotaryAngles angles;
    if (!m_kinematics) return angles;
    const Pose at = m_frame.toWorkpiece(m_programmed);
    auto machineAngle = [&](char letter) {
        const Axis axis = *axisFromLetter(letter);
        return at[axis] + m_settings.presetInMachine[axis];
    };
    angles.primaryDeg = machineAngle(m_kinematics->primary());
    if (m_kinematics->twoAxes()) angles.secondaryDeg = machineAngle(m_kinematics->secondary());
    return angles;
}

std::optional<machine::RotaryAngles> KlartextInterpreter::solvePlane(
    const Eigen::Matrix3d& rotation, PlaneBlock::Sequence sequence, bool tableRotation,
    std::string_view feature) {
    if (!m_kinematics) {
        if ((m_machineAxes & axisMaskOf("ABC")) == 0) {
            fail("not-supported", KERF_TR_NOOP("{1} needs rotary axes: this machine has none"),
                 {std::string(feature)});
        } else {
            fail("not-supported",
                 KERF_TR_NOOP("{1} needs the rotary tables described in the machine file "
                              "([kinematics], docs/machine-config.md)"),
                 {std::string(feature)});
        }
        return std::nullopt;
    }
    const machine::RotaryAngles current = currentTableAngles();
    const Vec3 toolAxis = rotation.col(2);
    machine::RotarySolutions solutions = m_kinematics->solve(toolAxis, current.secondaryDeg);
    if (tableRotation && solutions.count > 0) {
        const double aligned =
            m_kinematics->alignedSecondaryDeg(rotation.col(0), solutions.list[0].primaryDeg);
        solutions = m_kinematics->solve(toolAxis, aligned);
    }
    if (solutions.count == 0) {
        fail("plane",
             KERF_TR_NOOP("the rotary axes of this machine cannot turn the tool perpendicular to "
                          "this plane"));
        return std::nullopt;
    }
    auto chosen = m_kinematics->choose(solutions, choiceOf(sequence), current);
    if (!chosen) {
        std::string found;
        for (int i = 0; i < solutions.count; ++i) {
            const auto& s = solutions.list[static_cast<size_t>(i)];
            if (!found.empty()) found += ", ";
            found += std::string(1, m_kinematics->primary()) + formatFixed(s.primaryDeg, 3);
            if (m_kinematics->twoAxes()) {
                found += " " + std::string(1, m_kinematics->secondary()) +
                         formatFixed(s.secondaryDeg, 3);
            }
        }
        fail("plane",
             KERF_TR_NOOP("no solution for the rotary axes lies within their soft limits (and "
                          "the SEQ chosen): {1}"),
             {found});
        return std::nullopt;
    }
    return chosen;
}

void KlartextInterpreter::executePlane(const PlaneBlock& b) {
    if (!checkPathError(activePath().flush())) return;
    if (m_comp == CompWord::Left || m_comp == CompWord::Right) {
        fail("plane", KERF_TR_NOOP("PLANE with radius compensation RL/RR: program R0 first"));
        return;
    }
    auto rotation = planeRotation(b);
    if (!rotation) return;
    std::optional<machine::RotaryAngles> angles;
    if (b.kind == PlaneBlock::Kind::Reset) {
        angles = machine::RotaryAngles{};
    } else if (b.kind == PlaneBlock::Kind::Axial) {
        if (!m_kinematics) {
            solvePlane(*rotation, b.sequence, b.tableRotation, "PLANE");  // says what is missing
            return;
        }
        // Axis angles as written; an axis not written keeps its angle.
        angles = currentTableAngles();
        for (int i = 0; i < 3; ++i) {
            if (!b.axialPresent[static_cast<size_t>(i)]) continue;
            const char letter = "ABC"[i];
            if (letter == m_kinematics->primary()) {
                angles->primaryDeg = b.values[static_cast<size_t>(i)];
            } else if (m_kinematics->twoAxes() && letter == m_kinematics->secondary()) {
                angles->secondaryDeg = b.values[static_cast<size_t>(i)];
            } else {
                fail("plane",
                     KERF_TR_NOOP("PLANE AXIAL: {1} is not a rotary axis of the kinematics of "
                                  "this machine"),
                     {std::string(1, letter)});
                return;
            }
        }
        rotation = m_kinematics->toolFrame(*angles);
    } else {
        angles = solvePlane(*rotation, b.sequence, b.tableRotation, "PLANE");
        if (!angles) return;
    }
    TiltRequest request;
    request.rotation = *rotation;
    request.angles = *angles;
    request.reset = b.kind == PlaneBlock::Kind::Reset;
    request.positioning = b.positioning;
    request.distance = b.distance * lengthScale();
    request.rapid = b.feed.kind != FeedWord::Kind::Value;
    request.feed = b.feed.value;
    request.retractMax = b.retractMax;
    if (b.retract) request.retract = *b.retract * lengthScale();
    applyTilt(request);
}

void KlartextInterpreter::workingPlane(const CycleDefinition& def) {
    if (def.subNumber == 0) {
        // 19.0 alone: the next 19.1 gives the angles; a machine without rotary axes says no now.
        if ((m_machineAxes & axisMaskOf("ABC")) == 0) {
            fail("not-supported", KERF_TR_NOOP("{1} needs rotary axes: this machine has none"),
                 {"cycle 19 (working plane)"});
        }
        return;
    }
    Vec3 angles = Vec3::Zero();
    std::optional<double> feed;
    double distance = 0.0;
    for (const cycles::CycleWord& w : def.words) {
        if (!w.value) continue;
        if (w.key == "A" || w.key == "B" || w.key == "C") {
            angles[w.key[0] - 'A'] = *w.value;
        } else if (w.key == "F") {
            feed = *w.value;
        } else if (w.key == "DIST" || w.key == "ABST") {
            distance = *w.value * lengthScale();
        } else {
            fail("cycle-syntax", KERF_TR_NOOP("cycle 19: unexpected '{1}'"), {w.key});
            return;
        }
    }
    // The angles are spatial angles (the OEM's choice of the spec; Q120-Q122 get the axis
    // angles). All 0 resets the tilt. With F the control positions the rotary axes itself
    // (keeping the point DIST above the tool tip); without F the program positions them.
    TiltRequest request;
    request.reset = angles.isZero();
    request.rotation = spatialRotation(angles.x(), angles.y(), angles.z());
    if (!request.reset) {
        auto solution = solvePlane(request.rotation, PlaneBlock::Sequence::Shortest, false,
                                   "cycle 19 (working plane)");
        if (!solution) return;
        request.angles = *solution;
    }
    request.positioning = feed ? PlaneBlock::Positioning::Move : PlaneBlock::Positioning::Stay;
    request.distance = distance;
    request.rapid = false;
    request.feed = feed.value_or(0.0);
    applyTilt(request);
}

void KlartextInterpreter::applyTilt(const TiltRequest& request) {
    // Tilting the working plane ends the look-ahead of M120.
    if (!checkPathError(activePath().flush()) || !checkPathError(activePath().setLookAhead(0))) {
        return;
    }
    // Q120-Q122: the axis angles of the solution, for "L A+Q120 B+Q121 C+Q122".
    if (m_kinematics) {
        auto result = [this](char letter, double deg) {
            m_q.set(QRef{QKind::Q, static_cast<uint16_t>(120 + (letter - 'A'))}, deg);
        };
        result(m_kinematics->primary(), request.angles.primaryDeg);
        if (m_kinematics->twoAxes()) result(m_kinematics->secondary(), request.angles.secondaryDeg);
    }
    if (m_tcpm && request.positioning != PlaneBlock::Positioning::Stay) {
        fail("plane", KERF_TR_NOOP("with TCPM on the program positions the rotary axes: tilt with "
                                   "STAY, or switch TCPM off first"));
        return;
    }
    // The stream: linear axes of the machine.
    Pose at = m_tcpm ? m_path.machinePosition() : m_frame.toWorkpiece(m_programmed);
    // Where the axes stand now (they may differ from the old plane's angles after STAY).
    const machine::RotaryAngles oldAngles = m_kinematics ? tableAnglesOf(at) : m_tiltAngles;
    // The frame: tilt, then the axes' turn at the solved angles (the axes may still stand
    // elsewhere with STAY: the program positions them, as on the TNC).
    if (request.reset) {
        if (m_frame.tilted()) m_frame.clearTilt();
        m_tilt = TiltState{};
    } else {
        m_frame.setTilt(request.rotation);
        m_tilt.active = true;
        m_tilt.rotation = request.rotation;
    }
    m_tiltAngles = request.reset ? machine::RotaryAngles{} : request.angles;
    setTableFrame();
    if (request.positioning != PlaneBlock::Positioning::Stay && m_kinematics) {
        // MB: away from the part along the tool axis first.
        Pose retracted = at;
        const auto tool = static_cast<size_t>(axisIndex(m_toolAxis));
        if (request.retractMax) {
            const machine::AxisConfig* axis = m_settings.machine->axis(axisLetter(m_toolAxis));
            if (axis) {
                retracted.values[tool] = axis->maxLimit - m_settings.presetInMachine.values[tool] -
                                         m_tool.effectiveLength();
            }
        } else if (request.retract && *request.retract > 0.0) {
            // Along the tool, which a swivel head may have turned away from Z.
            retracted.setXyz(at.xyz() +
                             *request.retract * m_kinematics->headTurn(oldAngles) * Vec3::UnitZ());
        }
        // MB MAX never moves down; MB n always moves away along the tool.
        const bool away = request.retractMax ? retracted.values[tool] > at.values[tool]
                                             : (retracted.xyz() - at.xyz()).norm() > 1e-9;
        if (away) {
            emitStreamMove(at, retracted, true, 0.0);
            at = retracted;
        }
        Pose target = at;
        auto setAngle = [&](char letter, double deg) {
            const Axis axis = *axisFromLetter(letter);
            target[axis] = deg - m_settings.presetInMachine[axis];
        };
        setAngle(m_kinematics->primary(), request.angles.primaryDeg);
        if (m_kinematics->twoAxes())
            setAngle(m_kinematics->secondary(), request.angles.secondaryDeg);
        if (request.positioning == PlaneBlock::Positioning::Move) {
            // The point DIST along the tool from the tip stays where it is on the workpiece.
            const Vec3 preset = tiltPreset();
            const double length = m_tool.effectiveLength();
            const Vec3 kept = m_kinematics->tipOf(at.xyz(), oldAngles, preset, length) +
                              request.distance * m_kinematics->toolDirection(oldAngles);
            const Vec3 tip = kept - request.distance * m_kinematics->toolDirection(m_tiltAngles);
            target.setXyz(m_kinematics->axesOf(tip, m_tiltAngles, preset, length));
        }
        emitStreamMove(at, target, request.rapid, request.feed);
        at = target;
    }
    if (m_tcpm) {
        // The tip stays where it is on the part; the program counts it in the new plane.
        updatePathSpace();
        m_programmed = programOfPath(m_path.toolPosition());
        return;
    }
    m_programmed = m_frame.toProgram(at);
    updatePathSpace();
}

Vec3 KlartextInterpreter::tiltPreset() const {
    // The preset in machine coordinates: the run's, moved by cycle 247.
    return m_settings.presetInMachine.xyz() + m_frame.preset().xyz();
}

void KlartextInterpreter::setTableFrame() {
    m_tableTurn = Eigen::Matrix3d::Identity();
    m_tableOffset = Vec3::Zero();
    // With TCPM the kinematics turn the tip at the tables' real angles (klartext_tcpm.cpp).
    if (m_kinematics && m_tilt.active && !m_tcpm) {
        m_tableTurn = m_kinematics->workpieceToMachine(m_tiltAngles);
        m_tableOffset = m_kinematics->axesOf(Vec3::Zero(), m_tiltAngles, tiltPreset(),
                                             m_tool.effectiveLength());
    }
    m_frame.setTable(m_tableTurn, m_tableOffset);
}

void KlartextInterpreter::emitStreamMove(const Pose& from, const Pose& to, bool rapid,
                                         double feed) {
    if (activePath().space() != nullptr) {
        // The path works in another space: the axes move past it, straight.
        if (!checkPathError(activePath().flush())) return;
        activePath().addMachineLine(to, rapid, rapid ? m_feed : feed, m_at);
        return;
    }
    interp::PathMove move;
    move.geometry = ContourElement::line(workingPlane(), from, to);
    move.rapid = rapid;
    move.feed = rapid ? m_feed : feed;
    move.location = m_at;
    checkPathError(activePath().addMove(move));
}

double KlartextInterpreter::rotaryTarget(Axis axis, double current, double programmed,
                                         bool incremental) const {
    if (incremental) return current + programmed;
    const machine::AxisConfig* config =
        m_settings.machine ? m_settings.machine->axis(axisLetter(axis)) : nullptr;
    if (config == nullptr || !config->endless) return programmed;
    // An endless axis shows its angle modulo 360: without M126 it moves by the difference from
    // the shown angle (possibly the long way), with M126 the short way.
    const bool shortest = (m_shortestRotary || hasM(m_currentM, 126)) && !hasM(m_currentM, 127);
    if (shortest) return current + std::remainder(programmed - current, 360.0);
    const double shown = current - 360.0 * std::floor(current / 360.0);
    return current + programmed - shown;
}

bool KlartextInterpreter::rotaryWithinLimits(const Pose& programTarget) {
    if (m_settings.machine == nullptr) return true;
    // Most machines have no rotary axis with soft limits: then nothing needs transforming.
    if (!hasLimitedRotaryAxis(*m_settings.machine)) return true;
    return checkPathError(rotaryLimitError(m_frame.toWorkpiece(programTarget), m_at));
}

std::optional<interp::PathError> KlartextInterpreter::rotaryLimitError(
    const Pose& stream, const SourceLocation& location) const {
    if (m_settings.machine == nullptr) return std::nullopt;
    for (const machine::AxisConfig& axis : m_settings.machine->axes) {
        if (axis.type != machine::AxisType::Rotary || axis.endless || !axis.enabled) continue;
        const Axis a = *axisFromLetter(axis.letter);
        const double position = stream[a] + m_settings.presetInMachine[a];
        if (position < axis.minLimit - 1e-9 || position > axis.maxLimit + 1e-9) {
            return interp::PathError{
                location,
                "limit",
                KERF_TR_NOOP("the move would take axis {1} to {2} deg (machine coordinates), "
                             "beyond its soft limit {3}"),
                {std::string(1, axis.letter), formatFixed(position, 3),
                 formatFixed(position < axis.minLimit ? axis.minLimit : axis.maxLimit, 3)}};
        }
    }
    return std::nullopt;
}

}  // namespace kerf::klartext
