// FileHolders: which processes hold a file open (a serial port lkctl finds in use), from
// /proc/PID/fd: the same file through any path, this process never, the program named.

#include <system/FileHolders.h>

#include <QtCore/QFile>
#include <QtCore/QProcess>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using lk::system::FileHolder;
using lk::system::FileHolders;

class tst_FileHolders : public QObject {
    Q_OBJECT
private slots:
    void findsTheProcessThatHoldsIt();
    void ownProcessIsNotAHolder();
    void missingFileHasNone();
};

void tst_FileHolders::findsTheProcessThatHoldsIt()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("port"));
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.close();
    QVERIFY(FileHolders::of(path).isEmpty());
    QProcess sleeper; // holds the file as its standard input until killed
    sleeper.setStandardInputFile(path);
    sleeper.start(QStringLiteral("sleep"), {QStringLiteral("60")});
    QVERIFY(sleeper.waitForStarted());
    const QVector<FileHolder> holders = FileHolders::of(path);
    QCOMPARE(holders, (QVector<FileHolder>{{sleeper.processId(), QStringLiteral("sleep")}}));
    // The same file under another name.
    const QString link = dir.filePath(QStringLiteral("link"));
    QVERIFY(QFile::link(path, link));
    QCOMPARE(FileHolders::of(link), holders);
    sleeper.kill();
    sleeper.waitForFinished();
    QVERIFY(FileHolders::of(path).isEmpty());
}

void tst_FileHolders::ownProcessIsNotAHolder()
{
    QTemporaryDir dir;
    QFile f(dir.filePath(QStringLiteral("mine")));
    QVERIFY(f.open(QIODevice::WriteOnly));
    QVERIFY(FileHolders::of(f.fileName()).isEmpty());
}

void tst_FileHolders::missingFileHasNone()
{
    QVERIFY(FileHolders::of(QStringLiteral("/nonexistent/ttyUSB9")).isEmpty());
}

QTEST_GUILESS_MAIN(tst_FileHolders)
#include "tst_fileholders.moc"
