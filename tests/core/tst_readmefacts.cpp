// The READMEs (English and the Simplified Chinese mirror) state how many commands the codec
// implements; the count comes from the command table, so a command added or dropped there
// fails here until both READMEs say so.

#include <protocol/Command.h>

#include <QtCore/QFile>
#include <QtCore/QRegularExpression>
#include <QtTest/QTest>

using lk::protocol::CommandTable;

class tst_ReadmeFacts : public QObject {
    Q_OBJECT
private slots:
    void commandCounts_data();
    void commandCounts();
};

namespace {

int countOn(quint8 generationBit, bool only)
{
    int n = 0;
    for (const auto &info : CommandTable::all()) {
        if (info.canOnly) // the READMEs count the RS485 protocol's commands
            continue;
        const bool on = info.generations & generationBit;
        const bool elsewhere = info.generations & ~generationBit;
        if (on && !(only && elsewhere))
            ++n;
    }
    return n;
}

} // namespace

void tst_ReadmeFacts::commandCounts_data()
{
    QTest::addColumn<QString>("file");
    // Captures: all commands, those of V2.3, those V2.35 added.
    QTest::addColumn<QString>("pattern");
    QTest::newRow("README.md") << QStringLiteral("README.md")
                               << QStringLiteral("all (\\d+) commands \\(the (\\d+) of V2\\.3 and "
                                                 "the (\\d+) V2\\.35 added\\)");
    QTest::newRow("README.zh_CN.md")
        << QStringLiteral("README.zh_CN.md")
        << QStringLiteral("全部 (\\d+) 条命令（V2\\.3 的 (\\d+) 条与 V2\\.35 新增的 (\\d+) 条）");
}

void tst_ReadmeFacts::commandCounts()
{
    QFETCH(QString, file);
    QFETCH(QString, pattern);
    QFile readme(QStringLiteral(LK_SOURCE_DIR "/") + file);
    QVERIFY2(readme.open(QIODevice::ReadOnly), qPrintable(file));
    const QString text = QString::fromUtf8(readme.readAll());
    const QRegularExpressionMatch m = QRegularExpression(pattern).match(text);
    QVERIFY2(m.hasMatch(), qPrintable(file + QStringLiteral(" does not state the command count")));
    QCOMPARE(m.captured(1).toInt(), countOn(lk::protocol::kOnBoth, false));
    QCOMPARE(m.captured(2).toInt(), countOn(lk::protocol::kOnV23, false));
    QCOMPARE(m.captured(3).toInt(), countOn(lk::protocol::kOnV235, true));
}

QTEST_APPLESS_MAIN(tst_ReadmeFacts)
#include "tst_readmefacts.moc"
