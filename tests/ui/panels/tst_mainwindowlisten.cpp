// The whole window on a listen-only link (issue 22): counted at the transport, every action of
// every view and Esc write 0 bytes, and no view even asks the bus (no listen-only refusal);
// Esc says that nothing was sent; drives appear from what a tap hears another master and its
// drives say; a drive's series is chosen by the user and remembered; "Take over the bus"
// asks first, and then the tool transmits (polls, and Esc stops every drive).

#include "MainWindowFixture.h"
#include "TapTransport.h"

#include <drive/ConfirmDialog.h>
#include <main/ListenOnlyControl.h>
#include <panels/BusPanel.h>
#include <panels/ConnectionBar.h>
#include <panels/DriveRecord.h>
#include <panels/EmergencyStopButton.h>
#include <panels/SeriesChooser.h>
#include <text/VerdictText.h>

#include <sim/SimBusSpec.h>

#include <QtWidgets/QAbstractButton>
#include <QtWidgets/QApplication>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QMenu>
#include <QtWidgets/QPushButton>

using lk::protocol::Command;
using lk::ui::ConfirmDialog;
using lk::ui::ConfirmRequest;
using lk::ui::ConnectionChoice;
using namespace lk::uitest;

namespace {

/// What a tap hears when another master sends `command` to `id` on `bus` and the drive answers.
QByteArray exchange(lk::sim::SimBus &bus, Command command, int id, double t)
{
    const QByteArray request = lk::protocol::build::plain(command, id).request->encode();
    QByteArray heard = request;
    for (const auto &reply : bus.receive(request, t))
        heard += reply.bytes;
    return heard;
}

} // namespace

class tst_MainWindowListen : public MainWindowFixture {
    Q_OBJECT
private slots:
    void init();
    void cleanup();
    void opensListenOnlyAndSaysSo();
    void escapeSendsNothingAndSaysSo();
    void everyActionOfEveryViewWritesNothing();
    void drivesAppearFromObservedTraffic();
    void chosenSeriesIsRememberedPerPortAndId();
    void takeOverAsksFirstThenTransmits();

private:
    /// Listening to the simulated bus through the tap; nothing written.
    bool listen();
    /// Another master polls drives 5 (MS) and 6 (MF) and reads 6's model: the tap hears it.
    void hearOtherMaster(int rounds = 3);
    QList<QAbstractButton *> viewButtons() const;

    std::shared_ptr<TapLine> m_line;
    std::unique_ptr<lk::sim::SimBus> m_machine; ///< the running machine's drives
    double m_t = 0;
};

void tst_MainWindowListen::init()
{
    QVERIFY(openWindow());
    m_line = std::make_shared<TapLine>();
    m_window->controller()->addFactoryWrapper(
        [line = m_line](lk::bus::TransportFactory inner, const lk::ui::ConnectionChoice &) {
            return TapTransport::wrap(std::move(inner), line);
        });
    m_machine = lk::sim::SimBus::fromSpec(*lk::sim::SimBusSpec::parse(QStringLiteral("5:MS,6:MF")));
    m_t = 0;
}

void tst_MainWindowListen::cleanup()
{
    closeWindow();
    m_machine.reset();
    m_line.reset();
}

bool tst_MainWindowListen::listen()
{
    ConnectionChoice c = simulatorChoice();
    c.listenOnly = true;
    m_window->connectTo(c);
    return QTest::qWaitFor([this] { return model()->isListening(); }, kWaitMs);
}

void tst_MainWindowListen::hearOtherMaster(int rounds)
{
    for (int i = 0; i < rounds; ++i) {
        m_t += 0.01;
        QByteArray heard = exchange(*m_machine, Command::ReadState1, 5, m_t);
        heard += exchange(*m_machine, Command::ReadState2, 5, m_t);
        heard += exchange(*m_machine, Command::ReadState2, 6, m_t);
        heard += exchange(*m_machine, Command::ReadModel, 6, m_t);
        QVERIFY(m_line->hear(heard));
        QTest::qWait(30); // a gap between rounds, as a real master leaves
    }
}

QList<QAbstractButton *> tst_MainWindowListen::viewButtons() const
{
    // Everything but the connection bar (connect, take over: not actions on the bus).
    QList<QAbstractButton *> out;
    const auto all = m_window->findChildren<QAbstractButton *>();
    for (QAbstractButton *b : all) {
        if (!m_window->connectionBar()->isAncestorOf(b))
            out << b;
    }
    return out;
}

void tst_MainWindowListen::opensListenOnlyAndSaysSo()
{
    QVERIFY(listen());
    QVERIFY(m_line->opened > 0);
    QCOMPARE(m_line->readOnlyOpens.load(), m_line->opened.load());
    QVERIFY(m_window->connectionBar()->stateText().startsWith(
        QStringLiteral("Listen-only: this tool transmits nothing")));
    QVERIFY(m_window->connectionBar()->takeOverButton()->isVisibleTo(m_window.get()));
    QVERIFY(!model()->canSend());
    QTest::qWait(500); // a scan on connect would have begun by now
    QCOMPARE(m_line->written.load(), 0);
    QVERIFY(model()->ids().isEmpty());
    QCOMPARE(m_settings->connection().listenOnly, true);
}

void tst_MainWindowListen::escapeSendsNothingAndSaysSo()
{
    QVERIFY(listen());
    hearOtherMaster();
    QTRY_VERIFY_WITH_TIMEOUT(!model()->ids().isEmpty(), kWaitMs);
    QTest::keyClick(m_window.get(), Qt::Key_Escape);
    QTest::mouseClick(m_window->emergencyStopButton(), Qt::LeftButton);
    QCOMPARE(stopReport(), lk::text::VerdictText::listenOnlyStop());
    QCOMPARE(stopReport(), QStringLiteral("Listen-only: NOTHING was sent. Stop the machine with "
                                          "its own emergency stop."));
    QCOMPARE(m_window->banner()->entryLevel(lk::ui::EmergencyStopControl::entryKey()),
             lk::ui::MessageBanner::Level::Error);
    QTest::qWait(300);
    QCOMPARE(m_line->written.load(), 0);
    QCOMPARE(model()->statistics().listenOnlyRefusals, quint64(0)); // the bus was not even asked
}

void tst_MainWindowListen::everyActionOfEveryViewWritesNothing()
{
    QVERIFY(listen());
    hearOtherMaster();
    QTRY_VERIFY_WITH_TIMEOUT(model()->ids() == (QVector<int>{5, 6}), kWaitMs);
    // Whatever asks (ROM writes, zeroing, take-over) is answered yes: only gating may stop it.
    ConfirmDialog::ScopedPolicy yes([](const ConfirmRequest &) { return true; });
    // File dialogs and menus some buttons open are closed again at once.
    QTimer closer;
    connect(&closer, &QTimer::timeout, this, [] {
        if (QWidget *popup = QApplication::activePopupWidget())
            popup->close();
        if (QWidget *modal = QApplication::activeModalWidget())
            modal->close();
    });
    closer.start(20);
    int clicked = 0;
    for (const QString &view : m_window->viewNames()) {
        QVERIFY(m_window->showView(view));
        for (int id : {5, 6}) {
            model()->setCurrentId(id);
            QTest::qWait(50);
            for (QAbstractButton *b : viewButtons()) {
                if (!b->isEnabled() || !b->isVisible())
                    continue;
                b->click();
                ++clicked;
            }
            for (Qt::Key key : {Qt::Key_Left, Qt::Key_Right, Qt::Key_F5, Qt::Key_Escape})
                QTest::keyClick(m_window->currentView(), key);
        }
        QTest::qWait(50);
    }
    QVERIFY2(clicked > 10, qPrintable(QString::number(clicked)));
    hearOtherMaster(); // replies keep coming: nothing of ours may answer them
    QTest::qWait(500);
    QCOMPARE(m_line->written.load(), 0);
    QCOMPARE(model()->statistics().listenOnlyRefusals, quint64(0));
    QVERIFY(model()->isListening()); // no click took the bus over
}

void tst_MainWindowListen::drivesAppearFromObservedTraffic()
{
    QVERIFY(listen());
    hearOtherMaster();
    QTRY_COMPARE_WITH_TIMEOUT(model()->ids(), (QVector<int>{5, 6}), kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(model()->drive(5)->has(lk::bus::TelemetryField::Temperature), kWaitMs);
    // 6's model reply passed: its series is known. 5's never did: power or current is unknown.
    QTRY_COMPARE_WITH_TIMEOUT(model()->drive(6)->series, std::optional(lk::protocol::Series::MF),
                              kWaitMs);
    QVERIFY(!model()->drive(5)->series);
    QCOMPARE(m_line->written.load(), 0);
}

void tst_MainWindowListen::chosenSeriesIsRememberedPerPortAndId()
{
    QVERIFY(listen());
    hearOtherMaster();
    QTRY_VERIFY_WITH_TIMEOUT(model()->drive(5), kWaitMs);
    model()->setCurrentId(5);
    auto *chooser = m_window->busPanel()->seriesChooser();
    QVERIFY(chooser->isVisibleTo(m_window.get()));
    auto *combo = chooser->findChild<QComboBox *>(QStringLiteral("seriesCombo"));
    QCOMPARE(combo->currentText(), QStringLiteral("unknown"));
    combo->setCurrentIndex(combo->findText(QStringLiteral("MS")));
    emit combo->activated(combo->currentIndex());
    QTRY_COMPARE_WITH_TIMEOUT(model()->drive(5)->series, std::optional(lk::protocol::Series::MS),
                              kWaitMs);
    QCOMPARE(m_window->controller()->session()->knownMotors().value(5).series,
             std::optional(lk::protocol::Series::MS));
    QCOMPARE(m_settings->chosenSeries(QStringLiteral("simulator"), 5),
             std::optional(lk::protocol::Series::MS));
    QVERIFY(!m_settings->chosenSeries(QStringLiteral("simulator"), 6));
    // Next time on this port, drive 5 is decoded as MS as soon as it is seen.
    m_window->disconnectBus();
    QTRY_VERIFY_WITH_TIMEOUT(!model()->connection().isOpen(), kWaitMs);
    QVERIFY(listen());
    hearOtherMaster();
    QTRY_COMPARE_WITH_TIMEOUT(model()->drive(5) ? model()->drive(5)->series : std::nullopt,
                              std::optional(lk::protocol::Series::MS), kWaitMs);
    QCOMPARE(m_line->written.load(), 0);
}

void tst_MainWindowListen::takeOverAsksFirstThenTransmits()
{
    QVERIFY(listen());
    hearOtherMaster();
    QTRY_VERIFY_WITH_TIMEOUT(!model()->ids().isEmpty(), kWaitMs);
    QStringList asked;
    {
        ConfirmDialog::ScopedPolicy no([&asked](const ConfirmRequest &q) {
            asked << q.key;
            return false;
        });
        QTest::mouseClick(m_window->connectionBar()->takeOverButton(), Qt::LeftButton);
    }
    QCOMPARE(asked, QStringList{lk::ui::ListenOnlyControl::takeOverKey()});
    QTest::qWait(300);
    QVERIFY(model()->isListening());
    QCOMPARE(m_line->written.load(), 0);
    {
        ConfirmDialog::ScopedPolicy yes([](const ConfirmRequest &) { return true; });
        QTest::mouseClick(m_window->connectionBar()->takeOverButton(), Qt::LeftButton);
    }
    QTRY_VERIFY_WITH_TIMEOUT(model()->canSend(), kWaitMs);
    QVERIFY(!m_window->connectionBar()->takeOverButton()->isVisibleTo(m_window.get()));
    // The tool is the master now: it polls what it saw (or scans), and Esc stops every drive.
    QTRY_VERIFY_WITH_TIMEOUT(m_line->written > 0, kWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(model()->isPolling(), kWaitMs);
    const QVector<int> before = motorOffCounts();
    QTest::keyClick(m_window.get(), Qt::Key_Escape);
    for (int i = 0; i < kSimIds.size(); ++i)
        QTRY_VERIFY_WITH_TIMEOUT(sim()->requestCount(kSimIds[i], Command::MotorOff) > before[i],
                                 kWaitMs);
    QVERIFY(stopReport() != lk::text::VerdictText::listenOnlyStop());
}

QTEST_MAIN(tst_MainWindowListen)
#include "tst_mainwindowlisten.moc"
