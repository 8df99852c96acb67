#include "ts_file.h"

#include <QRegularExpression>
#include <QXmlStreamReader>
#include <algorithm>

namespace kerf::ui::test {

namespace {

QStringList sortedMatches(const QRegularExpression& pattern, const QString& text) {
    QStringList found;
    auto it = pattern.globalMatch(text);
    while (it.hasNext())
        found << it.next().captured(0);
    std::sort(found.begin(), found.end());
    return found;
}

// {1} for core's templates, %1 and %n for Qt's tr().
QStringList placeholders(const QString& text) {
    static const QRegularExpression pattern(QStringLiteral(R"(\{\d+\}|%L?\d+|%n)"));
    return sortedMatches(pattern, text);
}

// G01, M3, Q379, P25, D255, T-words: letters followed by digits stay as the control reads them.
QStringList codeWords(const QString& text) {
    static const QRegularExpression pattern(QStringLiteral(R"(\b[A-Z]{1,3}\d+\b)"));
    return sortedMatches(pattern, text);
}

// Klartext and Fagor keywords; a translation may repeat one but not drop it. Cycle names
// (sources all in capitals, such as "PGM CALL" or "POLAR PATTERN") are translated whole, as a
// TNC does, and are not checked.
QStringList keywords(const QString& text) {
    static const QRegularExpression pattern(QStringLiteral(
        R"((?<![A-Za-z0-9_])(CYCL|DEF|CALL|LBL|FN|PGM|BEGIN|END|FMAX|TOOL|PATTERN|APPR|DEP|BLK|)"
        R"(FORM|SEL|GLOBAL|DECLARE|SYSREAD|SYSSTR|REPOS|MCALL|MEXEC|PCALL|RPT|GPOS|RET|SUB|IF|)"
        R"(GOTO|TABOPEN|CC|CR|CT|LCT|RL|RR|QS|FAUTO|FZ|REP|IPA|CCA|LEN)(?![A-Za-z0-9_]))"));
    if (text.toUpper() == text) return {};
    return sortedMatches(pattern, text);
}

void readTranslation(QXmlStreamReader& xml, TsMessage& message) {
    const QString type = xml.attributes().value(QStringLiteral("type")).toString();
    message.finished = type.isEmpty();
    if (message.numerus) {
        while (xml.readNextStartElement()) {
            if (xml.name() == QLatin1String("numerusform"))
                message.translations << xml.readElementText();
            else
                xml.skipCurrentElement();
        }
    } else {
        message.translations << xml.readElementText();
    }
    for (const QString& text : message.translations)
        if (text.isEmpty()) message.finished = false;
    if (message.translations.isEmpty()) message.finished = false;
}

TsMessage readMessage(QXmlStreamReader& xml, const QString& context) {
    TsMessage message;
    message.context = context;
    message.numerus = xml.attributes().value(QStringLiteral("numerus")) == QLatin1String("yes");
    while (xml.readNextStartElement()) {
        if (xml.name() == QLatin1String("source"))
            message.source = xml.readElementText();
        else if (xml.name() == QLatin1String("comment"))
            message.disambiguation = xml.readElementText();
        else if (xml.name() == QLatin1String("translation"))
            readTranslation(xml, message);
        else
            xml.skipCurrentElement();
    }
    return message;
}

}  // namespace

TsFile readTsFile(QIODevice& device) {
    TsFile file;
    QXmlStreamReader xml(&device);
    QString context;
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement) continue;
        if (xml.name() == QLatin1String("TS"))
            file.language = xml.attributes().value(QStringLiteral("language")).toString();
        else if (xml.name() == QLatin1String("name"))
            context = xml.readElementText();
        else if (xml.name() == QLatin1String("message"))
            file.messages.push_back(readMessage(xml, context));
    }
    if (xml.hasError())
        file.xmlError = QStringLiteral("line %1: %2").arg(xml.lineNumber()).arg(xml.errorString());
    return file;
}

QStringList translationProblems(const TsMessage& message) {
    QStringList problems;
    for (const QString& text : message.translations) {
        if (placeholders(text) != placeholders(message.source))
            problems << QStringLiteral("placeholders differ in \"%1\"").arg(text);
        if (codeWords(text) != codeWords(message.source))
            problems << QStringLiteral("NC codes differ in \"%1\"").arg(text);
        const QStringList wanted = keywords(message.source);
        const QStringList given = keywords(text);
        for (const QString& word : wanted)
            if (given.count(word) < wanted.count(word))
                problems << QStringLiteral("keyword %1 missing in \"%2\"").arg(word, text);
    }
    problems.removeDuplicates();
    return problems;
}

}  // namespace kerf::ui::test
