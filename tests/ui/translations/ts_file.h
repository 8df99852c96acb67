#pragma once

#include <QIODevice>
#include <QString>
#include <QStringList>
#include <vector>

namespace kerf::ui::test {

// One <message> of a Qt Linguist .ts file.
struct TsMessage {
    QString context;
    QString source;
    QStringList translations;  // one text, or one per plural form of a numerus message
    bool numerus = false;
    bool finished = false;   // no type="unfinished" (or obsolete, vanished) and no empty text
    QString disambiguation;  // the <comment>: tells apart one source text's translations
};

struct TsFile {
    QString language;  // the language attribute of <TS>, such as "de_DE"
    std::vector<TsMessage> messages;
    QString xmlError;  // empty when the file is well-formed
};

TsFile readTsFile(QIODevice& device);

// What is wrong with one translated message, in words; empty when it is right: each translation
// keeps exactly the placeholders ({1}, %1, %n) of its source and the NC codes (G01, M3, Q379)
// and NC keywords (CYCL, LBL, FN ...) it names.
QStringList translationProblems(const TsMessage& message);

}  // namespace kerf::ui::test
