#include "core/tables/detail/tool_columns.h"

namespace kerf::tables::detail {

const std::vector<ColumnSpec>& toolColumns() {
    // Widths from a TOOL.T written by a TNC (pyLSV2's test file). Columns whose content differs
    // between software versions (TL, TYP, LIFTOFF, PLC ...) are not declared numeric so that
    // validation does not reject files from other versions.
    static const std::vector<ColumnSpec> columns = {
        otherColumn("T", 8),  // key: checked by readRowKeys
        textColumn("NAME", 32),
        numberColumn("L", 12, true, "+0"),
        numberColumn("R", 12, true, "+0"),
        numberColumn("R2", 12, true, "+0"),
        numberColumn("DL", 10, true, "+0"),
        numberColumn("DR", 10, true, "+0"),
        numberColumn("DR2", 10, true, "+0"),
        otherColumn("TL", 3, "0"),
        otherColumn("RT", 8),
        numberColumn("TIME1", 6, false, "0"),
        numberColumn("TIME2", 6, false, "0"),
        numberColumn("CUR_TIME", 9, false, "0"),
        otherColumn("TYP", 9, "0"),
        textColumn("DOC", 32),
        otherColumn("PLC", 10, "%00000000"),
        numberColumn("LCUTS", 12, true, "+0"),
        numberColumn("ANGLE", 8, true, "+0"),
        integerColumn("CUT", 5, "0"),
        numberColumn("LTOL", 7, false, "0"),
        numberColumn("RTOL", 7, false, "0"),
        numberColumn("R2TOL", 7, false, "0"),
        numberColumn("DIRECT", 8, true, "-1"),
        numberColumn("R-OFFS", 12, true),
        numberColumn("L-OFFS", 12, true, "+0"),
        numberColumn("LBREAK", 7, false, "0"),
        numberColumn("RBREAK", 7, false, "0"),
        numberColumn("NMAX", 10, false),
        otherColumn("LIFTOFF", 8, "0"),
        otherColumn("TP_NO", 7),
        numberColumn("T-ANGLE", 8, true, "+0"),
        numberColumn("PITCH", 8, true, "+0"),
        textColumn("LAST_USE", 20),
        otherColumn("PTYP", 5, "0"),
        otherColumn("AFC", 10),
        otherColumn("ACC", 4, "0"),
        textColumn("KINEMATIC", 20),
        otherColumn("OVRTIME", 8),
    };
    return columns;
}

}  // namespace kerf::tables::detail
