#include "E2eUtil.h"

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QRegularExpression>
#include <QtCore/QSet>
#include <QtCore/QTemporaryDir>
#include <QtTest/QTest>

#include <algorithm>

using namespace lk::e2e;

// Keeps the command-line reference (docs/CLI.md) and the man pages (packaging/man) true to the
// programs: every option a command's --help prints is documented in that command's section and
// nothing else is; the exit statuses match; and every example in a `console` block of CLI.md
// prints what is shown (exactly for encode/decode, the same JSON shape for the live commands,
// run against lksim).

namespace {

QString sourceFile(const QString &relative)
{
    QFile f(QStringLiteral(LK_SOURCE_DIR "/") + relative);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(f.readAll());
}

/// The body of each `# ` and `## ` heading of a Markdown text, by heading text; a body ends at
/// the next heading of level 1 or 2 (### stays inside).
QMap<QString, QString> sections(const QString &markdown)
{
    QMap<QString, QString> result;
    QString current;
    static const QRegularExpression heading(QStringLiteral("^#{1,2} (.+)$"));
    for (const QString &line : markdown.split(QLatin1Char('\n'))) {
        const auto m = heading.match(line);
        if (m.hasMatch()) {
            current = m.captured(1).trimmed();
            result[current];
            continue;
        }
        if (!current.isEmpty())
            result[current] += line + QLatin1Char('\n');
    }
    return result;
}

/// Every long option named in `text` (--port, --max-speed-dps; not --FIELD, not ---).
QSet<QString> optionsIn(const QString &text)
{
    static const QRegularExpression option(QStringLiteral("(?<![\\w-])--[a-z][a-z0-9-]*"));
    QSet<QString> found;
    for (auto it = option.globalMatch(text); it.hasNext();)
        found.insert(it.next().captured(0));
    return found;
}

/// The options a documented section covers: its own, plus the bus options when it refers to
/// them ("takes the [bus options](#bus-options)", "bus options (below)").
QSet<QString> documentedOptions(const QMap<QString, QString> &doc, const QString &section)
{
    QSet<QString> options = optionsIn(doc.value(section));
    if (doc.value(section).contains(QStringLiteral("bus options"), Qt::CaseInsensitive))
        options += optionsIn(doc.value(QStringLiteral("Bus options")));
    return options;
}

/// The options a QCommandLineParser help defines ("  -v, --version  ...", "  --link <path>  ..."),
/// not the ones its prose mentions (lksim's help names lkctl's --port).
QSet<QString> definedInHelp(const QString &help)
{
    static const QRegularExpression line(QStringLiteral("^  (?:-\\w, )?(--[a-z][a-z0-9-]*)"),
                                         QRegularExpression::MultilineOption);
    QSet<QString> found;
    for (auto it = line.globalMatch(help); it.hasNext();)
        found.insert(it.next().captured(1));
    return found;
}

/// The options a document section defines: the first cell of a table row ("| `--link PATH` |")
/// or a man page's term line ("**--link** *PATH*").
QSet<QString> definedInDoc(const QString &section)
{
    QSet<QString> found;
    for (const QString &line : section.split(QLatin1Char('\n'))) {
        if (line.startsWith(QStringLiteral("| `-")))
            found += optionsIn(line.section(QLatin1Char('|'), 1, 1));
        else if (line.startsWith(QStringLiteral("**-")))
            found += optionsIn(line);
    }
    return found;
}

/// The exit statuses a --help lists ("Exit status:" then lines "  N  text").
QSet<QString> helpExitStatuses(const QString &help)
{
    QSet<QString> codes;
    const qsizetype at = help.indexOf(QStringLiteral("Exit status"));
    static const QRegularExpression line(QStringLiteral("^  (\\d)  "),
                                         QRegularExpression::MultilineOption);
    for (auto it = line.globalMatch(help.mid(at)); at >= 0 && it.hasNext();)
        codes.insert(it.next().captured(1));
    return codes;
}

/// The exit statuses a section's table lists (rows "| N | ...").
QSet<QString> documentedExitStatuses(const QString &section)
{
    QSet<QString> codes;
    static const QRegularExpression row(QStringLiteral("^\\| (\\d) \\|"),
                                        QRegularExpression::MultilineOption);
    for (auto it = row.globalMatch(section); it.hasNext();)
        codes.insert(it.next().captured(1));
    return codes;
}

QString sorted(const QSet<QString> &set)
{
    QStringList list(set.begin(), set.end());
    std::sort(list.begin(), list.end());
    return list.join(QLatin1Char(' '));
}

/// "present in `a`, missing from `b`": the message that tells a developer what to add where.
QString difference(const QSet<QString> &a, const QString &aName, const QSet<QString> &b,
                   const QString &bName)
{
    QStringList parts;
    if (const QSet<QString> d = a - b; !d.isEmpty())
        parts << QStringLiteral("%1 has %2, %3 does not").arg(aName, sorted(d), bName);
    if (const QSet<QString> d = b - a; !d.isEmpty())
        parts << QStringLiteral("%1 has %2, %3 does not").arg(bName, sorted(d), aName);
    return parts.join(QStringLiteral("; "));
}

CtlResult run(const QString &program, const QStringList &args)
{
    return runProgram(program, args, QProcessEnvironment::systemEnvironment());
}

/// The subcommands `lkctl --help` lists, in its order.
QStringList lkctlCommands()
{
    const QString help = QString::fromUtf8(lkctl({QStringLiteral("--help")}).out);
    const qsizetype from = help.indexOf(QStringLiteral("Commands:\n"));
    QStringList names;
    if (from < 0)
        return names;
    for (const QString &line : help.mid(from).split(QLatin1Char('\n')).mid(1)) {
        if (!line.startsWith(QStringLiteral("  ")))
            break;
        names << line.trimmed().section(QLatin1Char(' '), 0, 0);
    }
    return names;
}

/// A JSON value's shape: keys and value types, arrays by their first element.
QString shape(const QJsonValue &v)
{
    switch (v.type()) {
    case QJsonValue::Object: {
        const QJsonObject o = v.toObject();
        QStringList parts;
        for (auto it = o.begin(); it != o.end(); ++it)
            parts << it.key() + QLatin1Char(':') + shape(it.value());
        return QLatin1Char('{') + parts.join(QLatin1Char(',')) + QLatin1Char('}');
    }
    case QJsonValue::Array: {
        const QJsonArray a = v.toArray();
        return QLatin1Char('[') + (a.isEmpty() ? QString() : shape(a.first())) + QLatin1Char(']');
    }
    case QJsonValue::Double:
        return QStringLiteral("number");
    case QJsonValue::String:
        return QStringLiteral("string");
    case QJsonValue::Bool:
        return QStringLiteral("bool");
    case QJsonValue::Null:
        return QStringLiteral("null");
    case QJsonValue::Undefined:
        break;
    }
    return QStringLiteral("undefined");
}

QString lineShape(const QByteArray &line)
{
    QJsonParseError error{};
    const QJsonDocument d = QJsonDocument::fromJson(line, &error);
    if (error.error != QJsonParseError::NoError)
        return QStringLiteral("not JSON: ") + QString::fromUtf8(line);
    return shape(d.isArray() ? QJsonValue(d.array()) : QJsonValue(d.object()));
}

/// One example of a `console` block: the command after "$ " and the lines it prints.
struct Example {
    QString section;
    QStringList args; ///< after "lkctl"
    QByteArray output;
};

/// The examples of every `console` block, in the document's order (the live ones change the
/// simulated drives: control moves drive 3, off stops it again).
QList<Example> consoleExamples(const QString &markdown)
{
    QList<Example> examples;
    QString section;
    bool inBlock = false;
    for (const QString &line : markdown.split(QLatin1Char('\n'))) {
        if (line.startsWith(QStringLiteral("## ")))
            section = line.mid(3);
        else if (line.startsWith(QStringLiteral("```")))
            inBlock = line == QStringLiteral("```console");
        else if (inBlock && line.startsWith(QStringLiteral("$ lkctl ")))
            examples.append({section, line.mid(8).split(QLatin1Char(' '), Qt::SkipEmptyParts), {}});
        else if (inBlock && !examples.isEmpty())
            examples.last().output += line.toUtf8() + '\n';
    }
    return examples;
}

} // namespace

class tst_CliReference : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void everyCommandHasASection();
    void optionsMatchHelp_data();
    void optionsMatchHelp();
    void exitStatusesMatchHelp_data();
    void exitStatusesMatchHelp();
    void lksimOptionsMatchHelp();
    void lkstudioOptionsMatchHelp();
    void examplesPrintWhatIsShown();

private:
    QMap<QString, QString> m_reference; ///< docs/CLI.md
    QMap<QString, QString> m_lkctlMan;  ///< packaging/man/lkctl.1.md
    QStringList m_commands;
};

void tst_CliReference::initTestCase()
{
    m_reference = sections(sourceFile(QStringLiteral("docs/CLI.md")));
    m_lkctlMan = sections(sourceFile(QStringLiteral("packaging/man/lkctl.1.md")));
    QVERIFY2(!m_reference.isEmpty(), "docs/CLI.md is missing");
    QVERIFY2(!m_lkctlMan.isEmpty(), "packaging/man/lkctl.1.md is missing");
    m_commands = lkctlCommands();
    QVERIFY2(m_commands.size() >= 11, qPrintable(m_commands.join(' ')));
}

void tst_CliReference::everyCommandHasASection()
{
    for (const QString &c : m_commands) {
        const QString section = QStringLiteral("lkctl ") + c;
        QVERIFY2(m_reference.contains(section), qPrintable("docs/CLI.md lacks ## " + section));
        QVERIFY2(m_lkctlMan.contains(section),
                 qPrintable("packaging/man/lkctl.1.md lacks ## " + section));
    }
}

void tst_CliReference::optionsMatchHelp_data()
{
    QTest::addColumn<QString>("command");
    for (const QString &c : lkctlCommands())
        QTest::newRow(qPrintable(c)) << c;
}

void tst_CliReference::optionsMatchHelp()
{
    QFETCH(QString, command);
    const CtlResult help = lkctl({command, QStringLiteral("--help")});
    QCOMPARE(help.exitCode, 0);
    const QSet<QString> helpOptions = optionsIn(QString::fromUtf8(help.out));
    const QString section = QStringLiteral("lkctl ") + command;
    const QString helpName = QStringLiteral("'lkctl %1 --help'").arg(command);
    const QString inReference =
        difference(helpOptions, helpName, documentedOptions(m_reference, section),
                   QStringLiteral("docs/CLI.md '## %1'").arg(section));
    QVERIFY2(inReference.isEmpty(), qPrintable(inReference));
    const QString inMan =
        difference(helpOptions, helpName, documentedOptions(m_lkctlMan, section),
                   QStringLiteral("packaging/man/lkctl.1.md '## %1'").arg(section));
    QVERIFY2(inMan.isEmpty(), qPrintable(inMan));
}

void tst_CliReference::exitStatusesMatchHelp_data()
{
    optionsMatchHelp_data();
}

void tst_CliReference::exitStatusesMatchHelp()
{
    QFETCH(QString, command);
    const CtlResult help = lkctl({command, QStringLiteral("--help")});
    const QSet<QString> fromHelp = helpExitStatuses(QString::fromUtf8(help.out));
    QVERIFY2(!fromHelp.isEmpty(), "no 'Exit status' in --help");
    const QString section = QStringLiteral("lkctl ") + command;
    const QString diff =
        difference(fromHelp, QStringLiteral("'lkctl %1 --help'").arg(command),
                   documentedExitStatuses(m_reference.value(section)),
                   QStringLiteral("the exit status table of docs/CLI.md '## %1'").arg(section));
    QVERIFY2(diff.isEmpty(), qPrintable(diff));
}

void tst_CliReference::lksimOptionsMatchHelp()
{
    const CtlResult help = run(QStringLiteral(LKSIM_PATH), {QStringLiteral("--help")});
    QCOMPARE(help.exitCode, 0);
    const QSet<QString> fromHelp = definedInHelp(QString::fromUtf8(help.out));
    QVERIFY(fromHelp.contains(QStringLiteral("--motors")));
    const QString inReference =
        difference(fromHelp, QStringLiteral("'lksim --help'"),
                   definedInDoc(m_reference.value(QStringLiteral("lksim"))),
                   QStringLiteral("the option table of docs/CLI.md '## lksim'"));
    QVERIFY2(inReference.isEmpty(), qPrintable(inReference));
    const auto man = sections(sourceFile(QStringLiteral("packaging/man/lksim.1.md")));
    const QString inMan = difference(fromHelp, QStringLiteral("'lksim --help'"),
                                     definedInDoc(man.value(QStringLiteral("OPTIONS"))),
                                     QStringLiteral("packaging/man/lksim.1.md OPTIONS"));
    QVERIFY2(inMan.isEmpty(), qPrintable(inMan));
}

void tst_CliReference::lkstudioOptionsMatchHelp()
{
#ifdef LKSTUDIO_PATH
    const CtlResult help = run(QStringLiteral(LKSTUDIO_PATH), {QStringLiteral("--help")});
    QCOMPARE(help.exitCode, 0);
    const QSet<QString> fromHelp = definedInHelp(QString::fromUtf8(help.out));
    QVERIFY(fromHelp.contains(QStringLiteral("--port")));
    const auto man = sections(sourceFile(QStringLiteral("packaging/man/lkstudio.1.md")));
    const QString diff = difference(fromHelp, QStringLiteral("'lkstudio --help'"),
                                    definedInDoc(man.value(QStringLiteral("OPTIONS"))),
                                    QStringLiteral("packaging/man/lkstudio.1.md OPTIONS"));
    QVERIFY2(diff.isEmpty(), qPrintable(diff));
#else
    QSKIP("built without the GUI (LK_BUILD_GUI=OFF)");
#endif
}

void tst_CliReference::examplesPrintWhatIsShown()
{
    const QList<Example> examples = consoleExamples(sourceFile(QStringLiteral("docs/CLI.md")));
    QVERIFY(examples.size() >= 10);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("lkbus"));
    LksimProcess sim(QStringLiteral(LKSIM_PATH));
    QVERIFY2(sim.start(simArgs(link)), qPrintable(sim.errorString()));

    for (const Example &e : examples) {
        QStringList args = e.args;
        const qsizetype port = args.indexOf(QStringLiteral("--port"));
        if (port >= 0)
            args[port + 1] = link; // the documented /dev/ttyUSB0 is lksim's bus here
        const CtlResult r = lkctl(args);
        const QString what =
            QStringLiteral("docs/CLI.md '## %1': lkctl %2\nprinted (exit %3):\n%4%5")
                .arg(e.section, e.args.join(QLatin1Char(' ')))
                .arg(r.exitCode)
                .arg(QString::fromUtf8(r.out), QString::fromUtf8(r.err));
        if (port < 0) { // no bus: the output is exact
            QVERIFY2(r.out == e.output, qPrintable(what));
            continue;
        }
        QVERIFY2(r.exitCode == 0, qPrintable(what));
        const QList<QByteArray> shown = e.output.trimmed().split('\n');
        const QList<QByteArray> printed = r.out.trimmed().split('\n');
        QVERIFY2(shown.size() == printed.size(), qPrintable(what));
        for (qsizetype i = 0; i < shown.size(); ++i) {
            const QString expected = lineShape(shown.at(i));
            const QString actual = lineShape(printed.at(i));
            QVERIFY2(expected == actual, qPrintable(QStringLiteral("%1\nshape shown:   %2\n"
                                                                   "shape printed: %3")
                                                        .arg(what, expected, actual)));
        }
    }
}

QTEST_GUILESS_MAIN(tst_CliReference)
#include "tst_clireference.moc"
