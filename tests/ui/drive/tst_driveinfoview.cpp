#include "DriveTestRig.h"

#include <drive/ConfirmDialog.h>
#include <drive/DriveInfoView.h>

#include <QtCore/QFile>
#include <QtCore/QJsonArray>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QTemporaryDir>
#include <QtGui/QClipboard>
#include <QtTest/QtTest>
#include <QtWidgets/QApplication>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPushButton>

using lk::drivetest::kWaitMs;
using lk::drivetest::SimRig;
using lk::protocol::Command;
using lk::ui::ConfirmDialog;
using lk::ui::ConfirmRequest;
using lk::ui::DriveInfoView;

class tst_DriveInfoView : public QObject {
    Q_OBJECT
private slots:
    void showsModelAndCopies();
    void showsV235Identity();
    void busReportHoldsEveryDrive();
    void confirmDialogDefaultsToCancel();
    void confirmDialogEscapeRejects();
};

void tst_DriveInfoView::showsModelAndCopies()
{
    SimRig rig;
    QVERIFY(rig.open());
    DriveInfoView view;
    view.setSession(&rig.session);
    view.setConnected(true);
    view.setDrive(2, rig.motor(2));
    view.show();
    const auto *fields = view.findChild<QLabel *>(QStringLiteral("fields"));
    QVERIFY(fields->text().contains(QStringLiteral("MG5010E-i10")));
    QVERIFY(fields->text().contains(QStringLiteral("1 : 10")));
    const QString text = view.infoText();
    QVERIFY(text.contains(QStringLiteral("Drive ID: 2")));
    QVERIFY(text.contains(QStringLiteral("Series: MG")));
    QVERIFY(text.contains(rig.motor(2).model->driverName));
    QVERIFY(text.contains(QStringLiteral("Firmware version: 2.3")));
    QTest::mouseClick(view.findChild<QPushButton *>(QStringLiteral("copy")), Qt::LeftButton);
    QCOMPARE(QApplication::clipboard()->text(), text);

    // Read again asks the drive.
    QTest::mouseClick(view.findChild<QPushButton *>(QStringLiteral("readModel")), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(view.statusText().contains(QStringLiteral("Model read")), kWaitMs);
}

// A V2.35 drive (58-byte 0x12): versions /100, the motor version and the binary unique ID
// as hex (docs/V2.35.md section 7; the simulator answers hw 300, motor 200, fw 235).
void tst_DriveInfoView::showsV235Identity()
{
    SimRig rig(QStringLiteral("1:MS4015@2.35"));
    QVERIFY(rig.open());
    DriveInfoView view;
    view.setSession(&rig.session);
    view.setConnected(true);
    view.setDrive(1, rig.motor(1));
    const QString text = view.infoText();
    QVERIFY2(text.contains(QStringLiteral("Firmware version: 2.35")), qPrintable(text));
    QVERIFY(text.contains(QStringLiteral("Hardware version: 3.00")));
    QVERIFY(text.contains(QStringLiteral("Motor version: 2.00")));
    QVERIFY(text.contains(QStringLiteral("Protocol: V2.35")));
    const QByteArray id = rig.motor(1).model->motorId;
    QCOMPARE(id.size(), 12);
    QVERIFY(text.contains(QStringLiteral("Unique ID: ") +
                          QString::fromLatin1(id.toHex(' ').toUpper())));
}

void tst_DriveInfoView::busReportHoldsEveryDrive()
{
    SimRig rig;
    QVERIFY(rig.open());
    DriveInfoView view;
    view.setSession(&rig.session);
    view.setConnected(true);
    view.setDrive(1, rig.motor(1));
    QSignalSpy ready(&view, &DriveInfoView::busReportReady);
    view.gatherBusReport();
    QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, kWaitMs);
    QTemporaryDir dir;
    const QString json = dir.filePath(QStringLiteral("report.json"));
    QCOMPARE(view.saveBusReport(json), QString());

    QFile f(json);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(f.readAll(), &error);
    QCOMPARE(error.error, QJsonParseError::NoError);
    const QJsonObject root = doc.object();
    QCOMPARE(root.value(QStringLiteral("format")).toString(),
             QStringLiteral("lkstudio-bus-report"));
    const QJsonArray drives = root.value(QStringLiteral("drives")).toArray();
    QCOMPARE(drives.size(), 4);
    const char *series[] = {"MF", "MG", "MS", "MH"};
    for (int i = 0; i < 4; ++i) {
        const QJsonObject d = drives.at(i).toObject();
        const int id = i + 1;
        QCOMPARE(d.value(QStringLiteral("id")).toInt(), id);
        QCOMPARE(d.value(QStringLiteral("series")).toString(), QLatin1String(series[i]));
        QCOMPARE(d.value(QStringLiteral("model"))
                     .toObject()
                     .value(QStringLiteral("motor_name"))
                     .toString(),
                 rig.motor(id).model->motorName);
        const QJsonObject pid = d.value(QStringLiteral("pid")).toObject();
        QCOMPARE(pid.value(QStringLiteral("speed_kp")).toInt(), int(rig.ramPid(id).speedKp));
        QCOMPARE(d.value(QStringLiteral("accel_dps2")).toInt(), 20000);
        QVERIFY(d.value(QStringLiteral("state1")).toObject().contains(QStringLiteral("voltage_v")));
        QVERIFY(d.value(QStringLiteral("problems")).toArray().isEmpty());
    }
    QFile html(DriveInfoView::htmlPathFor(json));
    QVERIFY(html.open(QIODevice::ReadOnly));
    const QString page = QString::fromUtf8(html.readAll());
    for (int id = 1; id <= 4; ++id)
        QVERIFY(page.contains(rig.motor(id).model->motorName));
}

void tst_DriveInfoView::confirmDialogDefaultsToCancel()
{
    ConfirmRequest q{QStringLiteral("test"), QStringLiteral("Title"), QStringLiteral("Really?"),
                     QStringLiteral("Because flash wears."), QStringLiteral("Do it")};
    ConfirmDialog dialog(q);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QTest::keyClick(&dialog, Qt::Key_Return);
    QCOMPARE(dialog.result(), int(QDialog::Rejected));
    QVERIFY(dialog.findChild<QLabel *>(QStringLiteral("reason"))->text().contains("flash"));
}

void tst_DriveInfoView::confirmDialogEscapeRejects()
{
    // Esc only rejects here: the emergency stop that Esc also means is lkstudio's own
    // application-wide handler (EmergencyStopControl, tested with the main window).
    ConfirmRequest q{QStringLiteral("test"), QStringLiteral("Title"), QStringLiteral("Really?"),
                     QStringLiteral("Because."), QStringLiteral("Do it")};
    ConfirmDialog dialog(q);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QTest::keyClick(&dialog, Qt::Key_Escape);
    QCOMPARE(dialog.result(), int(QDialog::Rejected));
}

QTEST_MAIN(tst_DriveInfoView)
#include "tst_driveinfoview.moc"
