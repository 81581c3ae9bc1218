// BoundedFile: how every file a user hands the tools is read. Only a regular file is opened,
// and only up to a bound: /dev/zero, a FIFO without a writer, a directory or a huge file is
// refused at once, saying what it is or how large it is.

#include <system/BoundedFile.h>

#include "../support/OddFiles.h"

#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QTemporaryDir>
#include <QtTest/QtTest>

using lk::system::BoundedFile;
using lk::system::FileReadError;
using lk::testsupport::OddFiles;

class tst_BoundedFile : public QObject {
    Q_OBJECT
private slots:
    void readsWithinTheBound_data();
    void readsWithinTheBound();
    void refuses_data();
    void refuses();
    void missingFileSaysWhy();
    void sizeText_data();
    void sizeText();

private:
    QTemporaryDir m_dir;
    QString path(const char *name) const { return m_dir.filePath(QLatin1String(name)); }
};

void tst_BoundedFile::readsWithinTheBound_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<qint64>("maxBytes");
    QTest::newRow("empty") << QByteArray() << qint64(10);
    QTest::newRow("small") << QByteArray("{\"a\":1}") << qint64(100);
    QTest::newRow("exactly the bound") << QByteArray(64, 'x') << qint64(64);
}

void tst_BoundedFile::readsWithinTheBound()
{
    QFETCH(QByteArray, bytes);
    QFETCH(qint64, maxBytes);
    const QString file = path("ok.txt");
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(bytes);
    f.close();
    const auto r = BoundedFile::read(file, maxBytes);
    QVERIFY2(r.ok(), r.error ? qPrintable(r.error->toString()) : "");
    QCOMPARE(r.bytes, bytes);
    // Through a symbolic link as well.
    const QString link = path("link.txt");
    QFile::remove(link);
    QVERIFY(QFile::link(file, link));
    QCOMPARE(BoundedFile::read(link, maxBytes).bytes, bytes);
}

void tst_BoundedFile::refuses_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<int>("expected");
    QTest::addColumn<QString>("said");
    QTest::newRow("FIFO without a writer")
        << int(OddFiles::Kind::Fifo) << int(FileReadError::Kind::NotRegularFile) << "a FIFO";
    QTest::newRow("directory") << int(OddFiles::Kind::Directory)
                               << int(FileReadError::Kind::NotRegularFile) << "a directory";
    QTest::newRow("/dev/zero") << int(OddFiles::Kind::Device)
                               << int(FileReadError::Kind::NotRegularFile) << "a character device";
    QTest::newRow("3 GB file") << int(OddFiles::Kind::Huge) << int(FileReadError::Kind::TooLarge)
                               << "it is 3000.0 MB, more than the 65536 bytes";
}

void tst_BoundedFile::refuses()
{
    QFETCH(int, kind);
    QFETCH(int, expected);
    QFETCH(QString, said);
    const QString target = m_dir.filePath(QStringLiteral("odd-%1").arg(kind));
    const QString made = OddFiles::make(OddFiles::Kind(kind), target, 3'000'000'000);
    QVERIFY(!made.isEmpty());
    QElapsedTimer clock;
    clock.start();
    const auto r = BoundedFile::read(made, 64 * 1024);
    QVERIFY(clock.elapsed() < 5000); // at once: no waiting for a writer, no reading 3 GB
    QVERIFY(!r.ok());
    QCOMPARE(int(r.error->kind), expected);
    QVERIFY(r.bytes.isEmpty());
    QCOMPARE(r.error->path, made);
    QVERIFY2(r.error->toString().contains(said), qPrintable(r.error->toString()));
    QVERIFY2(r.error->toString().contains(made), qPrintable(r.error->toString()));
    // Through a symbolic link the same.
    const QString link = target + QStringLiteral(".link");
    QVERIFY(QFile::link(made, link));
    QCOMPARE(int(BoundedFile::read(link, 64 * 1024).error->kind), expected);
}

void tst_BoundedFile::missingFileSaysWhy()
{
    const auto r = BoundedFile::read(path("none.json"), 100);
    QVERIFY(!r.ok());
    QCOMPARE(r.error->kind, FileReadError::Kind::CannotOpen);
    QVERIFY2(r.error->reason().contains(QLatin1String("No such file")),
             qPrintable(r.error->reason()));
}

void tst_BoundedFile::sizeText_data()
{
    QTest::addColumn<qint64>("bytes");
    QTest::addColumn<QString>("text");
    QTest::newRow("bytes") << qint64(9999) << "9999 bytes";
    QTest::newRow("under a megabyte") << qint64(999999) << "999999 bytes";
    QTest::newRow("MB") << qint64(130023424) << "130.0 MB";
}

void tst_BoundedFile::sizeText()
{
    QFETCH(qint64, bytes);
    QFETCH(QString, text);
    QCOMPARE(BoundedFile::sizeText(bytes), text);
}

QTEST_APPLESS_MAIN(tst_BoundedFile)
#include "tst_boundedfile.moc"
