#include <drive/DriveText.h>

#include <protocol/RequestBuilder.h>

#include <QtTest/QtTest>

using lk::bus::RequestResult;
using lk::bus::RequestStatus;
using lk::protocol::Command;

namespace {
RequestResult result(const lk::protocol::BuildResult &built, RequestStatus status, int attempts)
{
    RequestResult r;
    r.request = *built.request;
    r.status = status;
    r.attempts = attempts;
    r.reason = QStringLiteral("bad data checksum");
    return r;
}
} // namespace

/// The words the drive views use for a command whose reply was lost or corrupt: a motion
/// command that went out may have been acted on, and the text says so.
class tst_DriveText : public QObject {
    Q_OBJECT
private slots:
    void corruptMotionReplyMayHaveMoved_data();
    void corruptMotionReplyMayHaveMoved();
};

void tst_DriveText::corruptMotionReplyMayHaveMoved_data()
{
    namespace build = lk::protocol::build;
    QTest::addColumn<RequestResult>("r");
    QTest::addColumn<bool>("mayHaveMoved");
    // fw 2.35 spoils about 1 % of the 0xA4 replies' checksums: the drive moved all the same.
    QTest::newRow("corrupt 0xA4 reply")
        << result(build::multiPosition(3, 90, 360), RequestStatus::Error, 1) << true;
    QTest::newRow("speed, no reply")
        << result(build::speed(3, 360), RequestStatus::Timeout, 3) << true;
    QTest::newRow("never sent") << result(build::speed(3, 360), RequestStatus::Error, 0) << false;
    QTest::newRow("cancelled") << result(build::speed(3, 360), RequestStatus::Cancelled, 1)
                               << false;
    QTest::newRow("a read") << result(build::plain(Command::ReadState2, 3), RequestStatus::Error, 1)
                            << false;
}

void tst_DriveText::corruptMotionReplyMayHaveMoved()
{
    QFETCH(RequestResult, r);
    QFETCH(bool, mayHaveMoved);
    const QString text = lk::ui::DriveText::motionFailure(r);
    QVERIFY(text.startsWith(lk::ui::DriveText::failure(r)));
    QCOMPARE(text.contains(QStringLiteral("drive 3 may have acted on it and may be moving")),
             mayHaveMoved);
}

QTEST_MAIN(tst_DriveText)
#include "tst_drivetext.moc"
