// The emergency stop raced against a scan, end to end: the real lkstudio window on lksim over
// a pseudo-terminal (wire time at 115200 baud), four drives turning at 360 dps. Scan, then
// Esc after 0..200 ms: whatever the scan had found, every drive must end with its motor off,
// checked on lksim's own record of the frames it received.

#include "E2eUtil.h"
#include "E2eWindow.h"

#include <main/AppSettings.h>
#include <main/BusController.h>
#include <main/EmergencyStopControl.h>
#include <main/MainWindow.h>
#include <panels/BusModel.h>
#include <panels/ConnectionChoice.h>
#include <panels/MessageBanner.h>

#include <bus/BusSession.h>
#include <protocol/RequestBuilder.h>

#include <QtCore/QTemporaryDir>
#include <QtTest/QSignalSpy>
#include <QtTest/QTest>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QTabWidget>

#include <memory>

using namespace lk;

namespace {
constexpr int kWaitMs = 30000; // generous: the machine may be loaded
// Spread over the scan range, so that a scan finds them one by one over ~100 ms.
const QVector<int> kDrives{2, 9, 17, 30};

QByteArray framePrefix(quint8 command, int id)
{
    return QByteArray("3E ") + QByteArray::number(command, 16).toUpper() + ' ' +
           QByteArray::number(id, 16).toUpper().rightJustified(2, '0');
}
} // namespace

class tst_E2eEstop : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void cleanupTestCase();
    void escapeRacingAScanStopsEveryDrive_data();
    void escapeRacingAScanStopsEveryDrive();

private:
    QString report() const
    {
        return m_window->banner()->entryText(ui::EmergencyStopControl::entryKey());
    }
    /// Stop polling (the cancelled scan restarts it) and let the last replies pass.
    void quietBus()
    {
        m_window->controller()->session()->stopPolling();
        QTest::qWait(300);
    }
    /// Frames lksim received from the `mark`-th on, kept across reads.
    QList<QByteArray> framesSince(qsizetype mark);
    /// Which drives lksim last told to turn (speed) and never since to switch off.
    QVector<int> stillCommanded(const QList<QByteArray> &frames) const;

    QTemporaryDir m_dir;
    std::unique_ptr<e2e::LksimProcess> m_sim;
    std::unique_ptr<ui::AppSettings> m_settings;
    std::unique_ptr<ui::MainWindow> m_window;
    QList<QByteArray> m_frames;
};

void tst_E2eEstop::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_sim = std::make_unique<e2e::LksimProcess>(QStringLiteral(LKSIM_PATH));
    QVERIFY2(m_sim->start({"--motors", "2:MF,9:MG,17:MF,30:MG", "--wire-time", "--baud", "115200",
                           "--verbose"}),
             qPrintable(m_sim->errorString()));
    m_settings = std::make_unique<ui::AppSettings>(m_dir.filePath("lkstudio.ini"));
    // Scanning on connect finds the drives, then they are polled.
    e2e::openWindowOnLksim(m_window, m_settings.get(), m_sim->devicePath(), kDrives, kWaitMs);
}

void tst_E2eEstop::cleanupTestCase()
{
    m_window.reset();
    m_sim.reset();
}

QList<QByteArray> tst_E2eEstop::framesSince(qsizetype mark)
{
    m_frames = m_sim->receivedFrames(); // the whole log so far
    return m_frames.mid(mark);
}

QVector<int> tst_E2eEstop::stillCommanded(const QList<QByteArray> &frames) const
{
    QVector<int> ids;
    for (int id : kDrives) {
        qsizetype lastSpeed = -1, lastOff = -1;
        for (qsizetype i = 0; i < frames.size(); ++i) {
            if (frames.at(i).startsWith(framePrefix(0xA2, id)))
                lastSpeed = i;
            if (frames.at(i).startsWith(framePrefix(0x80, id)))
                lastOff = i;
        }
        if (lastSpeed >= 0 && lastOff < lastSpeed)
            ids.append(id);
    }
    return ids;
}

void tst_E2eEstop::escapeRacingAScanStopsEveryDrive_data()
{
    QTest::addColumn<int>("delayMs");
    for (int ms : {0, 20, 50, 100, 150, 200})
        QTest::newRow(qPrintable(QStringLiteral("Esc %1 ms after Scan").arg(ms))) << ms;
}

void tst_E2eEstop::escapeRacingAScanStopsEveryDrive()
{
    QFETCH(int, delayMs);
    bus::BusSession *session = m_window->controller()->session();
    quietBus(); // lksim's frame log can be read only while the bus is quiet
    const qsizetype mark = framesSince(0).size();
    for (int id : kDrives) // as the Control view would, for each drive
        session->send(*protocol::build::speed(id, 360).request);
    QTRY_COMPARE_WITH_TIMEOUT(stillCommanded(framesSince(mark)), kDrives, kWaitMs);

    QSignalSpy scans(session, &bus::BusSession::scanFinished);
    QSignalSpy reports(m_window->emergencyStopControl(), &ui::EmergencyStopControl::reported);
    QTest::mouseClick(m_window->findChild<QPushButton *>(QStringLiteral("scanButton")),
                      Qt::LeftButton);
    if (delayMs > 0)
        QTest::qWait(delayMs);
    QTest::keyClick(m_window->views(), Qt::Key_Escape);
    QTRY_COMPARE_WITH_TIMEOUT(reports.count(), 1, kWaitMs);
    // The stop saved the black box into the test's own folder, never the user's recordings.
    const auto saved = [this] {
        return m_window->banner()->entryText(ui::RecordingController::entryKey());
    };
    QTRY_VERIFY2_WITH_TIMEOUT(saved().contains(e2e::blackBoxFolder()), qPrintable(saved()),
                              kWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(scans.count(), 1, kWaitMs);
    quietBus();

    // On lksim: every drive's last word was motor_off, none is left turning.
    const QVector<int> turning = stillCommanded(framesSince(mark));
    QVERIFY2(turning.isEmpty(), qPrintable(QStringLiteral("still commanded: %1; report: %2")
                                               .arg(QString::number(turning.value(0)), report())));
    for (int id : kDrives) {
        const QList<QByteArray> frames = framesSince(mark);
        QVERIFY(std::any_of(frames.cbegin(), frames.cend(), [id](const QByteArray &f) {
            return f.startsWith(framePrefix(0x80, id));
        }));
    }
    QVERIFY2(report().contains(QStringLiteral("acknowledged by drive(s) 2, 9, 17, 30")),
             qPrintable(report()));
    QVERIFY2(!report().contains(QStringLiteral("NO answer")), qPrintable(report()));

    // Rescan, so that the next row starts with the four drives polled.
    QTest::mouseClick(m_window->findChild<QPushButton *>(QStringLiteral("scanButton")),
                      Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(scans.count(), 2, kWaitMs);
    QTRY_COMPARE_WITH_TIMEOUT(m_window->busModel()->ids(), kDrives, kWaitMs);
}

QTEST_MAIN(tst_E2eEstop)
#include "tst_e2eestop.moc"
