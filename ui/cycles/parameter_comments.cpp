#include "ui/cycles/parameter_comments.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <algorithm>
#include <iterator>

namespace kerf::ui {

namespace {

struct QComment {
    int q;
    const char* comment;
};
struct CycleComment {
    int cycle;
    int q;
    const char* comment;
};

// The short comments of the spec's program examples (tnc-machining-cycles.md), in Q order.
constexpr QComment kComments[] = {
    {1, QT_TRANSLATE_NOOP("kerf", "MILLING DEPTH")},
    {2, QT_TRANSLATE_NOOP("kerf", "TOOL PATH OVERLAP")},
    {3, QT_TRANSLATE_NOOP("kerf", "ALLOWANCE FOR SIDE")},
    {4, QT_TRANSLATE_NOOP("kerf", "ALLOWANCE FOR FLOOR")},
    {5, QT_TRANSLATE_NOOP("kerf", "SURFACE COORDINATE")},
    {6, QT_TRANSLATE_NOOP("kerf", "SET-UP CLEARANCE")},
    {7, QT_TRANSLATE_NOOP("kerf", "CLEARANCE HEIGHT")},
    {8, QT_TRANSLATE_NOOP("kerf", "ROUNDING RADIUS")},
    {9, QT_TRANSLATE_NOOP("kerf", "ROTATIONAL DIRECTION")},
    {10, QT_TRANSLATE_NOOP("kerf", "PLUNGING DEPTH")},
    {11, QT_TRANSLATE_NOOP("kerf", "FEED RATE FOR PLNGNG")},
    {12, QT_TRANSLATE_NOOP("kerf", "FEED RATE F. ROUGHNG")},
    {13, QT_TRANSLATE_NOOP("kerf", "ROUGH-OUT TOOL")},
    {14, QT_TRANSLATE_NOOP("kerf", "ALLOWANCE FOR SIDE")},
    {15, QT_TRANSLATE_NOOP("kerf", "CLIMB OR UP-CUT")},
    {16, QT_TRANSLATE_NOOP("kerf", "RADIUS")},
    {17, QT_TRANSLATE_NOOP("kerf", "TYPE OF DIMENSION")},
    {18, QT_TRANSLATE_NOOP("kerf", "COARSE ROUGHING TOOL")},
    {19, QT_TRANSLATE_NOOP("kerf", "FEED RATE FOR RECIP.")},
    {20, QT_TRANSLATE_NOOP("kerf", "SLOT WIDTH")},
    {21, QT_TRANSLATE_NOOP("kerf", "TOLERANCE")},
    {200, QT_TRANSLATE_NOOP("kerf", "SET-UP CLEARANCE")},
    {201, QT_TRANSLATE_NOOP("kerf", "DEPTH")},
    {202, QT_TRANSLATE_NOOP("kerf", "PLUNGING DEPTH")},
    {203, QT_TRANSLATE_NOOP("kerf", "SURFACE COORDINATE")},
    {204, QT_TRANSLATE_NOOP("kerf", "2ND SET-UP CLEARANCE")},
    {205, QT_TRANSLATE_NOOP("kerf", "MIN. PLUNGING DEPTH")},
    {206, QT_TRANSLATE_NOOP("kerf", "FEED RATE FOR PLNGNG")},
    {207, QT_TRANSLATE_NOOP("kerf", "FEED RATE FOR MILLING")},
    {208, QT_TRANSLATE_NOOP("kerf", "RETRACTION FEED RATE")},
    {210, QT_TRANSLATE_NOOP("kerf", "DWELL TIME AT TOP")},
    {211, QT_TRANSLATE_NOOP("kerf", "DWELL TIME AT DEPTH")},
    {212, QT_TRANSLATE_NOOP("kerf", "DECREMENT")},
    {213, QT_TRANSLATE_NOOP("kerf", "NR OF BREAKS")},
    {214, QT_TRANSLATE_NOOP("kerf", "DISENGAGING DIRECTN")},
    {215, QT_TRANSLATE_NOOP("kerf", "MACHINING OPERATION")},
    {216, QT_TRANSLATE_NOOP("kerf", "CENTER IN 1ST AXIS")},
    {217, QT_TRANSLATE_NOOP("kerf", "CENTER IN 2ND AXIS")},
    {218, QT_TRANSLATE_NOOP("kerf", "FIRST SIDE LENGTH")},
    {219, QT_TRANSLATE_NOOP("kerf", "2ND SIDE LENGTH")},
    {220, QT_TRANSLATE_NOOP("kerf", "CORNER RADIUS")},
    {222, QT_TRANSLATE_NOOP("kerf", "WORKPIECE BLANK DIA.")},
    {223, QT_TRANSLATE_NOOP("kerf", "CIRCLE DIAMETER")},
    {224, QT_TRANSLATE_NOOP("kerf", "ANGLE OF ROTATION")},
    {225, QT_TRANSLATE_NOOP("kerf", "STARTNG PNT 1ST AXIS")},
    {226, QT_TRANSLATE_NOOP("kerf", "STARTNG PNT 2ND AXIS")},
    {227, QT_TRANSLATE_NOOP("kerf", "STARTNG PNT 3RD AXIS")},
    {237, QT_TRANSLATE_NOOP("kerf", "SPACING IN 1ST AXIS")},
    {238, QT_TRANSLATE_NOOP("kerf", "SPACING IN 2ND AXIS")},
    {239, QT_TRANSLATE_NOOP("kerf", "THREAD PITCH")},
    {241, QT_TRANSLATE_NOOP("kerf", "NR OF REPETITIONS")},
    {242, QT_TRANSLATE_NOOP("kerf", "NUMBER OF COLUMNS")},
    {243, QT_TRANSLATE_NOOP("kerf", "NUMBER OF LINES")},
    {244, QT_TRANSLATE_NOOP("kerf", "PITCH CIRCLE DIAMETR")},
    {248, QT_TRANSLATE_NOOP("kerf", "ANGULAR LENGTH")},
    {245, QT_TRANSLATE_NOOP("kerf", "STARTING ANGLE")},
    {246, QT_TRANSLATE_NOOP("kerf", "STOPPING ANGLE")},
    {247, QT_TRANSLATE_NOOP("kerf", "STEPPING ANGLE")},
    {249, QT_TRANSLATE_NOOP("kerf", "DEPTH OF COUNTERBORE")},
    {250, QT_TRANSLATE_NOOP("kerf", "MATERIAL THICKNESS")},
    {251, QT_TRANSLATE_NOOP("kerf", "OFF-CENTER DISTANCE")},
    {252, QT_TRANSLATE_NOOP("kerf", "TOOL EDGE HEIGHT")},
    {253, QT_TRANSLATE_NOOP("kerf", "F PRE-POSITIONING")},
    {254, QT_TRANSLATE_NOOP("kerf", "F COUNTERSINKING")},
    {255, QT_TRANSLATE_NOOP("kerf", "DWELL TIME")},
    {256, QT_TRANSLATE_NOOP("kerf", "DIST FOR CHIP BRKNG")},
    {257, QT_TRANSLATE_NOOP("kerf", "DEPTH FOR CHIP BRKNG")},
    {258, QT_TRANSLATE_NOOP("kerf", "UPPER ADV STOP DIST")},
    {259, QT_TRANSLATE_NOOP("kerf", "LOWER ADV STOP DIST")},
    {301, QT_TRANSLATE_NOOP("kerf", "MOVE TO CLEARANCE")},
    {334, QT_TRANSLATE_NOOP("kerf", "PLUNGING DEPTH")},
    {335, QT_TRANSLATE_NOOP("kerf", "NOMINAL DIAMETER")},
    {336, QT_TRANSLATE_NOOP("kerf", "ANGLE OF SPINDLE")},
    {338, QT_TRANSLATE_NOOP("kerf", "INFEED FOR FINISHING")},
    {339, QT_TRANSLATE_NOOP("kerf", "DATUM NUMBER")},
    {342, QT_TRANSLATE_NOOP("kerf", "ROUGHING DIAMETER")},
    {343, QT_TRANSLATE_NOOP("kerf", "SELECT DIA./DEPTH")},
    {344, QT_TRANSLATE_NOOP("kerf", "DIAMETER")},
    {345, QT_TRANSLATE_NOOP("kerf", "SELECT POS. HEIGHT")},
    {347, QT_TRANSLATE_NOOP("kerf", "1ST LIMIT")},
    {348, QT_TRANSLATE_NOOP("kerf", "2ND LIMIT")},
    {349, QT_TRANSLATE_NOOP("kerf", "3RD LIMIT")},
    {350, QT_TRANSLATE_NOOP("kerf", "MILLING DIRECTION")},
    {351, QT_TRANSLATE_NOOP("kerf", "CLIMB OR UP-CUT")},
    {355, QT_TRANSLATE_NOOP("kerf", "THREADS PER STEP")},
    {356, QT_TRANSLATE_NOOP("kerf", "COUNTERSINKING DEPTH")},
    {357, QT_TRANSLATE_NOOP("kerf", "CLEARANCE TO SIDE")},
    {358, QT_TRANSLATE_NOOP("kerf", "DEPTH AT FRONT")},
    {359, QT_TRANSLATE_NOOP("kerf", "OFFSET AT FRONT")},
    {360, QT_TRANSLATE_NOOP("kerf", "COUNTERSINK PROCESS")},
    {365, QT_TRANSLATE_NOOP("kerf", "TYPE OF TRAVERSE")},
    {366, QT_TRANSLATE_NOOP("kerf", "PLUNGE")},
    {367, QT_TRANSLATE_NOOP("kerf", "TEXT POSITION")},
    {368, QT_TRANSLATE_NOOP("kerf", "ALLOWANCE FOR SIDE")},
    {369, QT_TRANSLATE_NOOP("kerf", "ALLOWANCE FOR FLOOR")},
    {370, QT_TRANSLATE_NOOP("kerf", "MAX. OVERLAP")},
    {374, QT_TRANSLATE_NOOP("kerf", "ANGLE OF ROTATION")},
    {375, QT_TRANSLATE_NOOP("kerf", "PITCH CIRCLE DIAMETR")},
    {376, QT_TRANSLATE_NOOP("kerf", "STARTING ANGLE")},
    {377, QT_TRANSLATE_NOOP("kerf", "NR OF REPETITIONS")},
    {378, QT_TRANSLATE_NOOP("kerf", "STEPPING ANGLE")},
    {379, QT_TRANSLATE_NOOP("kerf", "STARTING POINT")},
    {385, QT_TRANSLATE_NOOP("kerf", "FINISHING FEED RATE")},
    {386, QT_TRANSLATE_NOOP("kerf", "END POINT 3RD AXIS")},
    {389, QT_TRANSLATE_NOOP("kerf", "STRATEGY")},
    {390, QT_TRANSLATE_NOOP("kerf", "TYPE OF APPROACH")},
    {391, QT_TRANSLATE_NOOP("kerf", "RADIUS COMPENSATION")},
    {392, QT_TRANSLATE_NOOP("kerf", "RADIUS")},
    {393, QT_TRANSLATE_NOOP("kerf", "CENTER ANGLE")},
    {394, QT_TRANSLATE_NOOP("kerf", "DISTANCE")},
    {395, QT_TRANSLATE_NOOP("kerf", "DEPTH REFERENCE")},
    {401, QT_TRANSLATE_NOOP("kerf", "FEED RATE FACTOR")},
    {403, QT_TRANSLATE_NOOP("kerf", "RPM FACTOR")},
    {404, QT_TRANSLATE_NOOP("kerf", "FINE ROUGH STRATEGY")},
    {424, QT_TRANSLATE_NOOP("kerf", "WORKPC. BLANK SIDE 1")},
    {425, QT_TRANSLATE_NOOP("kerf", "WORKPC. BLANK SIDE 2")},
    {426, QT_TRANSLATE_NOOP("kerf", "DIR. OF SPINDLE ROT.")},
    {427, QT_TRANSLATE_NOOP("kerf", "ROT.SPEED INFEED/OUT")},
    {428, QT_TRANSLATE_NOOP("kerf", "ROT. SPEED DRILLING")},
    {429, QT_TRANSLATE_NOOP("kerf", "COOLANT ON")},
    {430, QT_TRANSLATE_NOOP("kerf", "COOLANT OFF")},
    {435, QT_TRANSLATE_NOOP("kerf", "DWELL DEPTH")},
    {436, QT_TRANSLATE_NOOP("kerf", "INFEED PER REV.")},
    {437, QT_TRANSLATE_NOOP("kerf", "APPROACH POSITION")},
    {439, QT_TRANSLATE_NOOP("kerf", "FEED RATE REFERENCE")},
    {446, QT_TRANSLATE_NOOP("kerf", "RESIDUAL MATERIAL")},
    {447, QT_TRANSLATE_NOOP("kerf", "CONNECTION DISTANCE")},
    {448, QT_TRANSLATE_NOOP("kerf", "PATH EXTENSION")},
    {500, QT_TRANSLATE_NOOP("kerf", "ENGRAVING TEXT")},
    {512, QT_TRANSLATE_NOOP("kerf", "FEED FOR APPROACH")},
    {513, QT_TRANSLATE_NOOP("kerf", "CHARACTER HEIGHT")},
    {514, QT_TRANSLATE_NOOP("kerf", "SPACE FACTOR")},
    {515, QT_TRANSLATE_NOOP("kerf", "FONT")},
    {516, QT_TRANSLATE_NOOP("kerf", "TEXT LAYOUT")},
    {517, QT_TRANSLATE_NOOP("kerf", "CIRCLE RADIUS")},
    {571, QT_TRANSLATE_NOOP("kerf", "REF-CIRCLE DIAMETER")},
    {572, QT_TRANSLATE_NOOP("kerf", "NUMBER OF CORNERS")},
    {573, QT_TRANSLATE_NOOP("kerf", "REFERENCE CIRCLE")},
    {574, QT_TRANSLATE_NOOP("kerf", "MAX. TEXT LENGTH")},
};

// Where a cycle names a shared parameter differently (thread depth, counterboring feed...).
constexpr CycleComment kCycleComments[] = {
    {25, 12, QT_TRANSLATE_NOOP("kerf", "FEED RATE FOR MILLING")},
    {29, 20, QT_TRANSLATE_NOOP("kerf", "RIDGE WIDTH")},
    {204, 254, QT_TRANSLATE_NOOP("kerf", "F COUNTERBORING")},
    {206, 201, QT_TRANSLATE_NOOP("kerf", "DEPTH OF THREAD")},
    {207, 201, QT_TRANSLATE_NOOP("kerf", "DEPTH OF THREAD")},
    {209, 201, QT_TRANSLATE_NOOP("kerf", "DEPTH OF THREAD")},
    {232, 202, QT_TRANSLATE_NOOP("kerf", "MAX. PLUNGING DEPTH")},
    {233, 202, QT_TRANSLATE_NOOP("kerf", "MAX. PLUNGING DEPTH")},
    {233, 370, QT_TRANSLATE_NOOP("kerf", "TOOL PATH OVERLAP")},
    {233, 389, QT_TRANSLATE_NOOP("kerf", "MILLING STRATEGY")},
    {241, 202, QT_TRANSLATE_NOOP("kerf", "MAX. PLUNGING DEPTH")},
    {251, 367, QT_TRANSLATE_NOOP("kerf", "POCKET POSITION")},
    {253, 218, QT_TRANSLATE_NOOP("kerf", "SLOT LENGTH")},
    {253, 219, QT_TRANSLATE_NOOP("kerf", "SLOT WIDTH")},
    {253, 367, QT_TRANSLATE_NOOP("kerf", "SLOT POSITION")},
    {254, 367, QT_TRANSLATE_NOOP("kerf", "REF. SLOT POSITION")},
    {256, 220, QT_TRANSLATE_NOOP("kerf", "RADIUS / CHAMFER")},
    {256, 367, QT_TRANSLATE_NOOP("kerf", "STUD POSITION")},
    {257, 223, QT_TRANSLATE_NOOP("kerf", "FINISHED PART DIA.")},
    {258, 220, QT_TRANSLATE_NOOP("kerf", "RADIUS / CHAMFER")},
    {275, 219, QT_TRANSLATE_NOOP("kerf", "SLOT WIDTH")},
    {276, 12, QT_TRANSLATE_NOOP("kerf", "FEED RATE FOR MILLING")},
    {262, 201, QT_TRANSLATE_NOOP("kerf", "DEPTH OF THREAD")},
    {263, 201, QT_TRANSLATE_NOOP("kerf", "DEPTH OF THREAD")},
    {264, 201, QT_TRANSLATE_NOOP("kerf", "DEPTH OF THREAD")},
    {264, 356, QT_TRANSLATE_NOOP("kerf", "TOTAL HOLE DEPTH")},
    {265, 201, QT_TRANSLATE_NOOP("kerf", "DEPTH OF THREAD")},
    {267, 201, QT_TRANSLATE_NOOP("kerf", "DEPTH OF THREAD")},
};

// A comment from the long description when the spec shows none: its first clause, upper case.
QString fromDescription(const char* description) {
    QString text = QCoreApplication::translate("kerf", description);
    const int cut = text.indexOf(QRegularExpression(QStringLiteral("[:(,]")));
    if (cut > 0) text = text.left(cut);
    return text.trimmed().left(kMaxCommentLength).toUpper();
}

}  // namespace

QString parameterComment(int cycle, const cycles::ParameterDescriptor& parameter) {
    const auto special =
        std::find_if(std::begin(kCycleComments), std::end(kCycleComments),
                     [&](const CycleComment& c) { return c.cycle == cycle && c.q == parameter.q; });
    if (special != std::end(kCycleComments))
        return QCoreApplication::translate("kerf", special->comment);
    const auto shared = std::find_if(std::begin(kComments), std::end(kComments),
                                     [&](const QComment& c) { return c.q == parameter.q; });
    if (parameter.q != 0 && shared != std::end(kComments))
        return QCoreApplication::translate("kerf", shared->comment);
    return fromDescription(parameter.description);
}

bool hasSpecComment(int cycle, int q) {
    return std::any_of(std::begin(kComments), std::end(kComments),
                       [&](const QComment& c) { return c.q == q; }) ||
           std::any_of(std::begin(kCycleComments), std::end(kCycleComments),
                       [&](const CycleComment& c) { return c.cycle == cycle && c.q == q; });
}

}  // namespace kerf::ui
