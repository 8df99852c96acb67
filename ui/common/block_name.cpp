#include "ui/common/block_name.h"

#include <QCoreApplication>

namespace kerf::ui {

namespace {

struct BlockName {
    Q_DECLARE_TR_FUNCTIONS(kerf::ui::BlockName)
};

bool usesNWords(program::Dialect dialect) {
    return dialect != program::Dialect::Klartext;
}

}  // namespace

QString blockShortName(int64_t blockNumber, int line, program::Dialect dialect) {
    if (blockNumber < 0) return BlockName::tr("line %1").arg(line);
    return usesNWords(dialect) ? QStringLiteral("N%1").arg(blockNumber)
                               : QString::number(blockNumber);
}

QString blockName(int64_t blockNumber, int line, program::Dialect dialect) {
    if (blockNumber < 0) return BlockName::tr("Line %1").arg(line);
    if (usesNWords(dialect)) return QStringLiteral("N%1").arg(blockNumber);
    return BlockName::tr("Block %1").arg(blockNumber);
}

}  // namespace kerf::ui
