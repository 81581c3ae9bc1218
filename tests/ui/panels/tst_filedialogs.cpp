// FileDialogs: suggested names say what, which drive and when; each purpose remembers its
// folder in the settings, and a save dialog (here the traffic export's) starts there.

#include "../../support/FileSizeLimit.h"

#include <main/AppSettings.h>
#include <panels/BusModel.h>
#include <panels/FileDialogs.h>
#include <panels/TrafficPanel.h>

#include <QtCore/QTemporaryDir>
#include <QtCore/QTimer>
#include <QtTest/QtTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QFileDialog>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QMessageBox>

using lk::ui::FileDialogs;
using Purpose = lk::ui::FileDialogs::Purpose;

namespace {
const QDateTime kWhen(QDate(2026, 11, 23), QTime(12, 3, 59));

/// Answer the next modal file dialog: record where it starts, then accept `fileName`.
void answerFileDialog(QString *startDir, QString *startName, const QString &fileName)
{
    QTimer::singleShot(50, [=] {
        auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
        if (!dialog) {
            answerFileDialog(startDir, startName, fileName); // not up yet
            return;
        }
        *startDir = dialog->directory().absolutePath();
        *startName = dialog->findChild<QLineEdit *>(QStringLiteral("fileNameEdit"))->text();
        // Type the path into the name field, as a user would: selectFile() alone may leave
        // the suggested name there, which accept() then takes.
        dialog->selectFile(fileName);
        dialog->findChild<QLineEdit *>(QStringLiteral("fileNameEdit"))->setText(fileName);
        static_cast<QDialog *>(dialog)->accept(); // QFileDialog::accept, checks the name
    });
}
/// Read the next modal message box's text, then close it.
void answerMessageBox(QString *text)
{
    QTimer::singleShot(50, [=] {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (!box) {
            answerMessageBox(text); // the file dialog is still up, or the box not yet
            return;
        }
        *text = box->text();
        box->accept();
    });
}
} // namespace

class tst_FileDialogs : public QObject {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void suggestedName_data();
    void suggestedName();
    void foldersAreRememberedPerPurpose();
    void missingFolderFallsBack();
    void trafficExportStartsInTheRememberedFolder();
    void failedTrafficExportIsShown();

private:
    QTemporaryDir m_dir;
    std::unique_ptr<lk::ui::AppSettings> m_settings;
};

void tst_FileDialogs::init()
{
    m_settings = std::make_unique<lk::ui::AppSettings>(m_dir.filePath("lkstudio.ini"));
    auto *s = m_settings.get();
    FileDialogs::setFolderMemory(
        {[s](const QString &p) { return s->lastFolder(p); },
         [s](const QString &p, const QString &folder) { s->setLastFolder(p, folder); }});
}

void tst_FileDialogs::cleanup()
{
    FileDialogs::setFolderMemory({});
    m_settings.reset();
    QFile::remove(m_dir.filePath("lkstudio.ini"));
}

void tst_FileDialogs::suggestedName_data()
{
    QTest::addColumn<QString>("what");
    QTest::addColumn<QVector<int>>("ids");
    QTest::addColumn<QString>("suffix");
    QTest::addColumn<QString>("expected");
    QTest::newRow("plot of one drive") << "plot" << QVector<int>{1} << "csv"
                                       << "lk-id1-plot-2026-11-23-1203.csv";
    QTest::newRow("plot of two drives") << "plot" << QVector<int>{1, 7} << "png"
                                        << "lk-id1-id7-plot-2026-11-23-1203.png";
    QTest::newRow("no drive") << "traffic" << QVector<int>{} << "txt"
                              << "lk-traffic-2026-11-23-1203.txt";
    QTest::newRow("model name tidied") << "MG5010E i36/x parameters" << QVector<int>{3} << "json"
                                       << "lk-id3-MG5010E-i36-x-parameters-2026-11-23-1203.json";
}

void tst_FileDialogs::suggestedName()
{
    QFETCH(QString, what);
    QFETCH(QVector<int>, ids);
    QFETCH(QString, suffix);
    QFETCH(QString, expected);
    QCOMPARE(FileDialogs::suggestedName(what, ids, kWhen, suffix), expected);
}

void tst_FileDialogs::foldersAreRememberedPerPurpose()
{
    QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("plots")));
    QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("reports")));
    FileDialogs::remember(Purpose::PlotCsv, m_dir.filePath(QStringLiteral("plots/a.csv")));
    FileDialogs::remember(Purpose::BusReport, m_dir.filePath(QStringLiteral("reports/r.json")));
    FileDialogs::remember(Purpose::Traffic, QString()); // a cancelled dialog changes nothing
    QCOMPARE(FileDialogs::startFolder(Purpose::PlotCsv), m_dir.filePath(QStringLiteral("plots")));
    QCOMPARE(FileDialogs::startFolder(Purpose::BusReport),
             m_dir.filePath(QStringLiteral("reports")));

    // Kept in the settings file: a new AppSettings on the same file reads it back.
    m_settings->sync();
    lk::ui::AppSettings again(m_dir.filePath("lkstudio.ini"));
    QCOMPARE(again.lastFolder(FileDialogs::purposeKey(Purpose::PlotCsv)),
             m_dir.filePath(QStringLiteral("plots")));
    QCOMPARE(again.lastFolder(FileDialogs::purposeKey(Purpose::Traffic)), QString());
}

void tst_FileDialogs::missingFolderFallsBack()
{
    FileDialogs::remember(Purpose::PlotImage, m_dir.filePath(QStringLiteral("gone/x.png")));
    const QString start = FileDialogs::startFolder(Purpose::PlotImage);
    QVERIFY(start != m_dir.filePath(QStringLiteral("gone")));
    QVERIFY(QFileInfo(start).isDir());
}

void tst_FileDialogs::trafficExportStartsInTheRememberedFolder()
{
    QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("logs")));
    const QString logs = m_dir.filePath(QStringLiteral("logs"));
    m_settings->setLastFolder(FileDialogs::purposeKey(Purpose::Traffic), logs);
    lk::ui::BusModel model;
    lk::ui::TrafficPanel panel(&model);
    QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("elsewhere")));
    const QString chosen = m_dir.filePath(QStringLiteral("elsewhere/t.txt"));
    QString startDir, startName;
    answerFileDialog(&startDir, &startName, chosen);
    panel.exportWithDialog();
    QCOMPARE(startDir, logs);
    QVERIFY2(QRegularExpression(QStringLiteral("^lk-traffic-\\d{4}-\\d\\d-\\d\\d-\\d{4}\\.txt$"))
                 .match(startName)
                 .hasMatch(),
             qPrintable(startName));
    QVERIFY(QFile::exists(chosen));
    QCOMPARE(FileDialogs::startFolder(Purpose::Traffic),
             m_dir.filePath(QStringLiteral("elsewhere")));
}

void tst_FileDialogs::failedTrafficExportIsShown()
{
    lk::ui::BusModel model;
    lk::ui::TrafficPanel panel(&model);
    const QString chosen = m_dir.filePath(QStringLiteral("full-disk.txt"));
    QString startDir, startName, shown;
    answerFileDialog(&startDir, &startName, chosen);
    answerMessageBox(&shown);
    {
        const lk::testsupport::FileSizeLimit diskFull(16); // less than the log's header
        QVERIFY(diskFull.isActive());
        panel.exportWithDialog();
    }
    // Told as the plot exports tell it (a warning naming the file), and nothing left behind.
    QVERIFY2(shown.startsWith(QStringLiteral("Cannot write ")) && shown.contains(chosen),
             qPrintable(shown));
    QVERIFY(!QFile::exists(chosen));
}

QTEST_MAIN(tst_FileDialogs)
#include "tst_filedialogs.moc"
