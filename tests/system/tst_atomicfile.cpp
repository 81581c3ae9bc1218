// AtomicFile: the one writer behind every file the tools save (parameter sets, CSV, ROM files,
// plot images). The path holds the whole new content or what it held before - also when the
// disk fills up, where Qt 6.4's QSaveFile alone would rename a cut copy into place.

#include <system/AtomicFile.h>

#include "../support/FileSizeLimit.h"

#include <QtCore/QDir>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using lk::system::AtomicFile;

namespace {
QByteArray contents(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<missing>");
}
} // namespace

class tst_AtomicFile : public QObject {
    Q_OBJECT
private slots:
    void writesTheWholeFile();
    void fullDiskKeepsTheEarlierFile_data();
    void fullDiskKeepsTheEarlierFile();
    void destroyedUncommittedLeavesNothing();
    void failedDeviceWriterIsNotCommitted();
    void unwritableFolderIsReported();
};

void tst_AtomicFile::writesTheWholeFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.txt"));
    QCOMPARE(AtomicFile::writeAll(path, "one\n"), QString());
    QCOMPARE(contents(path), QByteArray("one\n"));
    AtomicFile f(path);
    QVERIFY(f.open());
    QVERIFY(f.write("two\n"));
    QVERIFY(f.write("three\n"));
    QCOMPARE(contents(path), QByteArray("one\n")); // nothing shows before the commit
    QVERIFY(f.commit());
    QCOMPARE(contents(path), QByteArray("two\nthree\n"));
}

void tst_AtomicFile::fullDiskKeepsTheEarlierFile_data()
{
    // A short file sits in QSaveFile's buffer until commit(): the case the flush before the
    // rename is for. A long one fails in write() already.
    QTest::addColumn<int>("bytes");
    QTest::newRow("short, fails in the flush") << 100;
    QTest::newRow("long, fails in write") << 100000;
}

void tst_AtomicFile::fullDiskKeepsTheEarlierFile()
{
    QFETCH(int, bytes);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.txt"));
    QCOMPARE(AtomicFile::writeAll(path, "earlier\n"), QString());
    QString why;
    {
        const lk::testsupport::FileSizeLimit diskFull(16);
        QVERIFY(diskFull.isActive());
        why = AtomicFile::writeAll(path, QByteArray(bytes, 'x'));
    }
    QVERIFY2(!why.isEmpty(), "a write past a full disk must fail");
    QCOMPARE(contents(path), QByteArray("earlier\n"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("a.txt")});
}

void tst_AtomicFile::destroyedUncommittedLeavesNothing()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.txt"));
    {
        AtomicFile f(path);
        QVERIFY(f.open());
        QVERIFY(f.write("half"));
    }
    QVERIFY(!QFile::exists(path));
    QVERIFY(QDir(dir.path()).entryList(QDir::Files).isEmpty());
}

void tst_AtomicFile::failedDeviceWriterIsNotCommitted()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("a.png"));
    QCOMPARE(AtomicFile::writeAll(path, "earlier"), QString());
    AtomicFile f(path);
    QVERIFY(f.open());
    f.device()->write("cut");
    f.fail(QStringLiteral("the encoder gave up"));
    QVERIFY(!f.commit());
    QCOMPARE(f.errorString(), QStringLiteral("the encoder gave up"));
    QCOMPARE(contents(path), QByteArray("earlier"));
}

void tst_AtomicFile::unwritableFolderIsReported()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("no/such/folder/a.txt"));
    AtomicFile f(path);
    QVERIFY(!f.open());
    QVERIFY(!f.errorString().isEmpty());
    QVERIFY(!f.commit());
    QVERIFY(!AtomicFile::writeAll(path, "x").isEmpty());
}

QTEST_APPLESS_MAIN(tst_AtomicFile)
#include "tst_atomicfile.moc"
