#include <QBuffer>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QSet>
#include <QTextStream>

#include <gtest/gtest.h>

#include "ts_file.h"

// Checks translations/kerf_<lang>.ts: well-formed, every text translated (except those listed in
// translations/unfinished.txt), placeholders and NC codes kept, and every operator message of
// core (KERF_TR_NOOP) present in the "kerf" context.
namespace kerf::ui::test {
namespace {

const QString kTranslations = QStringLiteral(KERF_SOURCE_DIR "/translations");

QStringList tsFileNames() {
    return QDir(kTranslations).entryList({QStringLiteral("kerf_*.ts")}, QDir::Files, QDir::Name);
}

TsFile readTsFileNamed(const QString& name) {
    QFile file(kTranslations + QLatin1Char('/') + name);
    if (!file.open(QIODevice::ReadOnly)) return {{}, {}, QStringLiteral("cannot open ") + name};
    return readTsFile(file);
}

TsFile readTsText(const QByteArray& text) {
    QBuffer buffer;
    buffer.setData(text);
    buffer.open(QIODevice::ReadOnly);
    return readTsFile(buffer);
}

// "de: source text" lines, \n written as a backslash and n; # starts a comment.
QSet<QString> listedUnfinished() {
    QSet<QString> listed;
    QFile file(kTranslations + QStringLiteral("/unfinished.txt"));
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) return listed;
    QTextStream in(&file);
    in.setCodec("UTF-8");
    while (!in.atEnd()) {
        const QString line = in.readLine();
        if (line.isEmpty() || line.startsWith(QLatin1Char('#'))) continue;
        listed.insert(QString(line).replace(QStringLiteral("\\n"), QStringLiteral("\n")));
    }
    return listed;
}

QString languageOf(const QString& fileName) {
    return fileName.mid(5, fileName.size() - 8);  // kerf_<lang>.ts
}

TEST(TranslationFiles, ShipGermanSpanishPolishAndPortuguese) {
    EXPECT_EQ(tsFileNames(), (QStringList{"kerf_de.ts", "kerf_es.ts", "kerf_pl.ts", "kerf_pt.ts"}));
    EXPECT_EQ(readTsFileNamed("kerf_de.ts").language, QStringLiteral("de_DE"));
    EXPECT_EQ(readTsFileNamed("kerf_es.ts").language, QStringLiteral("es_ES"));
}

TEST(TranslationFiles, EveryTextIsTranslatedAndKeepsItsPlaceholders) {
    const QSet<QString> listed = listedUnfinished();
    for (const QString& name : tsFileNames()) {
        const TsFile file = readTsFileNamed(name);
        ASSERT_TRUE(file.xmlError.isEmpty())
            << name.toStdString() << ": " << file.xmlError.toStdString();
        EXPECT_GT(file.messages.size(), 900u) << name.toStdString();
        for (const TsMessage& message : file.messages) {
            const QString key = languageOf(name) + QStringLiteral(": ") + message.source;
            if (!message.finished) {
                EXPECT_TRUE(listed.contains(key))
                    << name.toStdString() << ": not translated: " << message.source.toStdString();
                continue;
            }
            for (const QString& problem : translationProblems(message))
                ADD_FAILURE() << name.toStdString() << ": \"" << message.source.toStdString()
                              << "\": " << problem.toStdString();
        }
    }
}

TEST(TranslationFiles, AllLanguagesListTheSameTexts) {
    QSet<QString> first;
    for (const QString& name : tsFileNames()) {
        QSet<QString> texts;
        for (const TsMessage& message : readTsFileNamed(name).messages)
            texts.insert(message.context + QLatin1Char('\t') + message.source + QLatin1Char('\t') +
                         message.disambiguation);
        if (first.isEmpty())
            first = texts;
        else
            EXPECT_EQ(texts, first) << name.toStdString() << ": run translations/update_ts.sh";
    }
}

// The text of a C++ string literal's body: \n is a line break, \" a quote, \\ a backslash.
QString unescaped(const QString& body) {
    QString text;
    for (int i = 0; i < body.size(); ++i) {
        if (body[i] != QLatin1Char('\\') || i + 1 == body.size()) {
            text += body[i];
            continue;
        }
        const QChar next = body[++i];
        text += next == QLatin1Char('n') ? QChar('\n') : next;
    }
    return text;
}

// C++ string literals of KERF_TR_NOOP("..." "...") and KERF_TR_NOOP3("...", "disambiguation")
// in core and motion, read independently of lupdate: the text, a tab and the disambiguation (if
// any).
QSet<QString> coreMessageTemplates() {
    static const QRegularExpression call(QStringLiteral(
        R"re(KERF_TR_NOOP(3?)\(\s*((?:"(?:[^"\\]|\\.)*"\s*)+)(?:,\s*"((?:[^"\\]|\\.)*)"\s*)?\))re"));
    static const QRegularExpression literal(QStringLiteral(R"re("((?:[^"\\]|\\.)*)")re"));
    QSet<QString> templates;
    QStringList files;
    // motion/ too: the planner's refusals reach the operator (they were never translated).
    for (const char* folder : {"/core", "/motion"}) {
        QDirIterator it(QStringLiteral(KERF_SOURCE_DIR) + QLatin1String(folder), {"*.h", "*.cpp"},
                        QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext())
            files << it.next();
    }
    for (const QString& path : files) {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly)) continue;
        const QString code = QString::fromUtf8(file.readAll());
        auto calls = call.globalMatch(code);
        while (calls.hasNext()) {
            const auto match = calls.next();
            QString text;
            auto parts = literal.globalMatch(match.captured(2));
            while (parts.hasNext())
                text += unescaped(parts.next().captured(1));
            templates.insert(text + QLatin1Char('\t') + unescaped(match.captured(3)));
        }
    }
    return templates;
}

TEST(TranslationFiles, HoldEveryCoreMessageInTheKerfContext) {
    const QSet<QString> templates = coreMessageTemplates();
    EXPECT_GT(templates.size(), 800);
    for (const QString& name : tsFileNames()) {
        QSet<QString> kerfContext;
        for (const TsMessage& message : readTsFileNamed(name).messages)
            if (message.context == QLatin1String("kerf"))
                kerfContext.insert(message.source + QLatin1Char('\t') + message.disambiguation);
        for (const QString& text : templates)
            EXPECT_TRUE(kerfContext.contains(text))
                << name.toStdString() << " lacks \"" << text.toStdString()
                << "\" (text, tab, disambiguation): run translations/update_ts.sh";
    }
}

TEST(TranslationChecks, FindADroppedPlaceholderCodeOrKeyword) {
    TsMessage message{QStringLiteral("kerf"),
                      QStringLiteral("cycle {1}: Q{2} = {3} is too large"),
                      {QStringLiteral("Zyklus {1}: Q{2} = {3} ist zu groß")},
                      false,
                      true,
                      {}};
    EXPECT_TRUE(translationProblems(message).isEmpty());
    message.translations = QStringList{QStringLiteral("Zyklus {1}: Q{2} ist zu groß")};
    EXPECT_EQ(translationProblems(message).size(), 1);
    message.translations = QStringList{QStringLiteral("Zyklus {1}: Q{2} = {2} ist zu groß")};
    EXPECT_EQ(translationProblems(message).size(), 1);

    const TsMessage code{QStringLiteral("kerf"),
                         QStringLiteral("G37 needs G01"),
                         {QStringLiteral("G37 braucht eine Gerade")},
                         false,
                         true,
                         {}};
    EXPECT_EQ(translationProblems(code).size(), 1);
    const TsMessage keyword{QStringLiteral("kerf"),
                            QStringLiteral("no CYCL DEF before"),
                            {QStringLiteral("keine Zyklusdefinition davor")},
                            false,
                            true,
                            {}};
    EXPECT_EQ(translationProblems(keyword).size(), 2);  // CYCL and DEF
    const TsMessage qtStyle{QStringLiteral("MainWindow"),
                            QStringLiteral("Copy %1 to:"),
                            {QStringLiteral("Kopieren nach:")},
                            false,
                            true,
                            {}};
    EXPECT_EQ(translationProblems(qtStyle).size(), 1);
}

TEST(TranslationChecks, FindADroppedPlaceholderInARealFile) {
    QFile file(kTranslations + QStringLiteral("/kerf_de.ts"));
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    QByteArray text = file.readAll();
    const QByteArray right =
        "<translation>Zyklus {1}: die Gewindesteigung Q{2} ist 0</translation>";
    const QByteArray wrong = "<translation>Zyklus {1}: die Gewindesteigung Q ist 0</translation>";
    ASSERT_TRUE(text.contains(right));
    text.replace(right, wrong);
    int broken = 0;
    for (const TsMessage& message : readTsText(text).messages)
        if (message.finished && !translationProblems(message).isEmpty()) ++broken;
    EXPECT_EQ(broken, 1);
}

TEST(TranslationChecks, ReadUnfinishedAndNumerusMessages) {
    const TsFile file = readTsText(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?><TS version=\"2.1\" language=\"pl_PL\">"
        "<context><name>kerf</name>"
        "<message><source>stop</source><translation type=\"unfinished\"></translation></message>"
        "<message><source>empty</source><translation></translation></message>"
        "<message numerus=\"yes\"><source>%n more</source><translation>"
        "<numerusform>%n wiecej</numerusform><numerusform>%n wiecej</numerusform>"
        "<numerusform>%n</numerusform></translation></message>"
        "</context></TS>");
    ASSERT_TRUE(file.xmlError.isEmpty());
    EXPECT_EQ(file.language, QStringLiteral("pl_PL"));
    ASSERT_EQ(file.messages.size(), 3u);
    EXPECT_FALSE(file.messages[0].finished);
    EXPECT_FALSE(file.messages[1].finished);
    EXPECT_TRUE(file.messages[2].finished);
    EXPECT_EQ(file.messages[2].translations.size(), 3);
    EXPECT_TRUE(translationProblems(file.messages[2]).isEmpty());
    EXPECT_FALSE(readTsText("<TS><context><name>kerf</name></TS>").xmlError.isEmpty());
}

}  // namespace
}  // namespace kerf::ui::test
