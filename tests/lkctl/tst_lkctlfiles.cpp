#include "E2eUtil.h"

#include "../support/OddFiles.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

// The files lkctl is given (--limits FILE.json) are read with a bound: /dev/zero, a FIFO
// nobody writes to, a directory or a file far past a limits file's size is refused at once
// (exit 2, nothing sent), naming what it is or how large, instead of aborting with
// std::bad_alloc or waiting forever.

using lk::e2e::CtlResult;
using lk::testsupport::OddFiles;

class tst_LkctlFiles : public QObject {
    Q_OBJECT
private slots:
    void limitsFileIsBounded_data();
    void limitsFileIsBounded();
    void limitsFileAtTheBoundIsRead();

private:
    QTemporaryDir m_dir;
};

void tst_LkctlFiles::limitsFileIsBounded_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("said");
    QTest::newRow("/dev/zero") << int(OddFiles::Kind::Device) << "it is a character device";
    QTest::newRow("FIFO without a writer") << int(OddFiles::Kind::Fifo) << "it is a FIFO";
    QTest::newRow("directory") << int(OddFiles::Kind::Directory) << "it is a directory";
    QTest::newRow("1 GB") << int(OddFiles::Kind::Huge)
                          << "it is 1000.0 MB, more than the 65536 bytes";
}

void tst_LkctlFiles::limitsFileIsBounded()
{
    QFETCH(int, kind);
    QFETCH(QString, said);
    const QString path =
        OddFiles::make(OddFiles::Kind(kind),
                       m_dir.filePath(QString::fromLatin1(QTest::currentDataTag())), 1'000'000'000);
    QVERIFY(!path.isEmpty());
    for (const char *command : {"control 3 speed 10", "step 3 speed 0 10"}) {
        QElapsedTimer clock;
        clock.start();
        const CtlResult r =
            lk::e2e::lkctl(QString::fromLatin1(command).split(QLatin1Char(' ')) +
                               QStringList{QStringLiteral("--limits"), path,
                                           QStringLiteral("--sim"), QStringLiteral("3:MF")},
                           30000);
        QVERIFY2(clock.elapsed() < 25000, "lkctl must not wait for the file");
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(r.out, QByteArray());
        QVERIFY2(r.err.contains("cannot read --limits " + path.toUtf8()), r.err.constData());
        QVERIFY2(r.err.contains(said.toUtf8()), r.err.constData());
        QVERIFY2(r.err.contains("nothing was sent"), r.err.constData());
    }
}

void tst_LkctlFiles::limitsFileAtTheBoundIsRead()
{
    // The bound is the size of a file, not of its JSON: spaces up to 64 KiB still read.
    const QString path = m_dir.filePath(QStringLiteral("padded.json"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    const QByteArray json = "{\"max_speed_dps\": 50}";
    f.write(json + QByteArray(64 * 1024 - json.size(), ' '));
    f.close();
    CtlResult r =
        lk::e2e::lkctl({"control", "3", "speed", "60", "--limits", path, "--sim", "3:MF"});
    QCOMPARE(r.exitCode, 4); // read, and its 50 dps limit applied
    QVERIFY2(r.err.contains("50"), r.err.constData());
    f.open(QIODevice::Append);
    f.write(" ");
    f.close();
    r = lk::e2e::lkctl({"control", "3", "speed", "60", "--limits", path, "--sim", "3:MF"});
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains("it is 65537 bytes, more than the 65536 bytes"), r.err.constData());
}

QTEST_GUILESS_MAIN(tst_LkctlFiles)
#include "tst_lkctlfiles.moc"
