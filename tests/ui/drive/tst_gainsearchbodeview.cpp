// The suggested gains' Bode in the Tuning view (#25: "the best beside the current gains (step
// overlay and Bode)") on the built-in simulated bus: with "Measure the Bode of both" (on by
// default) the search's best and the gains read are drawn side by side with their bandwidth
// and peak, each candidate's step comes from its score, the drive's RAM holds the gains read
// afterwards, and Esc in the best's sweep stops the motor and puts the gains read back.
#include "DriveTestRig.h"

#include <drive/ConfirmDialog.h>
#include <drive/FrequencyTuningView.h>
#include <drive/GainSearchView.h>
#include <drive/GainSearchViewOutcome.h>
#include <drive/TuningView.h>
#include <safety/SoftLimits.h>
#include <tuning/BodeChart.h>
#include <tuning/StepOverlayChart.h>

#include <QtCharts/QLineSeries>
#include <QtCharts/QScatterSeries>
#include <QtTest/QtTest>
#include <QtWidgets/QCheckBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QTableWidget>

using lk::drivetest::kWaitMs;
using lk::drivetest::SimRig;
using lk::protocol::Command;
using lk::ui::ConfirmDialog;
using lk::ui::ConfirmRequest;
using lk::ui::GainSearchView;
using lk::ui::TuningView;

Q_DECLARE_METATYPE(lk::tuning::SearchEnd)
Q_DECLARE_METATYPE(lk::tuning::DriveLeft)

namespace {

constexpr int kSearchWaitMs = 300000; // a search and two sweeps on a loaded 2-core machine

struct Opened {
    std::unique_ptr<TuningView> view;
    GainSearchView *search = nullptr;
};

Opened openView(SimRig &rig, int id)
{
    Opened o;
    o.view = lk::drivetest::showView<TuningView>(rig, id, QSize(1366, 728));
    const auto limits = lk::safety::SoftLimits::defaults(rig.motor(id).series);
    o.view->setStepTestLimits([limits](QString *) { return std::optional(limits); });
    o.search = o.view->findChild<lk::ui::FrequencyTuningView *>()->search();
    if (!QTest::qWaitFor([&] { return o.view->readComplete() && !o.view->isBusy(); }, kWaitMs))
        o.view.reset();
    return o;
}

bool samePid(const lk::protocol::PidGains &a, const lk::protocol::PidGains &b)
{
    return a.angleKp == b.angleKp && a.angleKi == b.angleKi && a.speedKp == b.speedKp &&
           a.speedKi == b.speedKi && a.iqKp == b.iqKp && a.iqKi == b.iqKi;
}

bool motorOn(SimRig &rig, int id)
{
    return rig.read<bool>(id, [](const lk::sim::SimDrive &d) { return d.motorOn(); });
}

QString rowText(QTableWidget *t, const QString &name, int column)
{
    for (int r = 0; r < t->rowCount(); ++r) {
        if (t->verticalHeaderItem(r) && t->verticalHeaderItem(r)->text() == name)
            return t->item(r, column)->text();
    }
    return {};
}

/// Every confirmation answered yes.
struct Yes {
    ConfirmDialog::ScopedPolicy policy{[](const ConfirmRequest &) { return true; }};
};

} // namespace

class tst_GainSearchBodeView : public QObject {
    Q_OBJECT
private slots:
    void outcomeWords_data();
    void outcomeWords();
    void boxSaysHowLong();
    void bodeOfBothBesideTheGainsRead();
    void escInTheBestsSweepRestores();
};

void tst_GainSearchBodeView::outcomeWords_data()
{
    using lk::tuning::DriveLeft;
    using lk::tuning::SearchEnd;
    QTest::addColumn<SearchEnd>("end");
    QTest::addColumn<DriveLeft>("drive");
    QTest::addColumn<bool>("restored");
    QTest::addColumn<QString>("message"); // the runner's English, never read for the words
    QTest::addColumn<QString>("text");
    QTest::newRow("Esc: off, gains back")
        << SearchEnd::AbortedByUser << DriveLeft::Off << true << QString()
        << "Stopped. Motor Off went to drive 4 and it acknowledged. The gains read are back in "
           "RAM.";
    QTest::newRow("an emergency stop, Motor Off unanswered")
        << SearchEnd::EmergencyStop << DriveLeft::MayBeMoving << true
        << "the Bode step: a sweep ended: aborted: drive 4 is off; back in RAM"
        << "Stopped by an emergency stop. Drive 4 did not acknowledge Motor Off: it may still be "
           "moving. The gains read are back in RAM.";
    QTest::newRow("gains not written back")
        << SearchEnd::FailedToRestore << DriveLeft::Off << false << "are back in RAM"
        << "The gains read could not be written back at the end: it stopped. Motor Off went to "
           "drive 4 and it acknowledged. The gains read before could NOT be written back: read "
           "the drive and check them.";
    QTest::newRow("not read") << SearchEnd::FailedToRead << DriveLeft::Untouched << true
                              << "drive 4 is off"
                              << "The gains of drive 4 could not be read. Nothing was sent.";
    QTest::newRow("unstable, back at speed")
        << SearchEnd::Unstable << DriveLeft::BackAtSpeed << true << "holds 0 dps"
        << "1 candidate(s) tried in 3 s; none stayed within the bounds. The search stopped at the "
           "first unstable candidate. Drive 4 is back at 150 dps, the speed it had, and keeps "
           "turning until stopped. The gains read are back in RAM.";
}

void tst_GainSearchBodeView::outcomeWords()
{
    QFETCH(lk::tuning::SearchEnd, end);
    QFETCH(lk::tuning::DriveLeft, drive);
    QFETCH(bool, restored);
    QFETCH(QString, message);
    QFETCH(QString, text);
    lk::tuning::GainSearchResult r;
    r.spec.id = 4;
    r.seconds = 3;
    r.candidates.resize(1);
    r.outcome.end = end;
    r.outcome.drive = drive;
    r.outcome.speedDps = 150;
    r.outcome.gainsRestored = restored;
    r.message = message;
    QCOMPARE(lk::ui::GainSearchViewOutcome::text(r), text);
}

void tst_GainSearchBodeView::boxSaysHowLong()
{
    SimRig rig;
    QVERIFY(rig.open());
    Opened o = openView(rig, 1);
    QVERIFY(o.view);
    auto *box = o.search->findChild<QCheckBox *>(QStringLiteral("measureBode"));
    auto *travel = o.search->findChild<QLabel *>(QStringLiteral("searchTravel"));
    QVERIFY(box && box->isChecked() && o.search->spec().measureBode);
    QVERIFY2(travel->text().contains(QStringLiteral("The Bode of both adds about")),
             qPrintable(travel->text()));
    box->setChecked(false);
    QVERIFY(!o.search->spec().measureBode);
    QVERIFY(!travel->text().contains(QStringLiteral("Bode")));
}

void tst_GainSearchBodeView::bodeOfBothBesideTheGainsRead()
{
    SimRig rig;
    QVERIFY(rig.open());
    Opened o = openView(rig, 1);
    QVERIFY(o.view);
    const lk::protocol::PidGains before = rig.ramPid(1);
    Yes yes;
    QVERIFY(o.search->runSearch());
    QTRY_VERIFY_WITH_TIMEOUT(!o.search->isRunning(), kSearchWaitMs);
    const auto &result = o.search->result();
    QVERIFY2(result && result->ok(), qPrintable(o.search->statusText()));
    QVERIFY2(result->best && *result->best > 0, qPrintable(o.search->statusText()));
    // Each step drawn is its candidate's own (from its score).
    QCOMPARE(o.search->overlay()->runCount(), 2);
    QCOMPARE(o.search->overlay()->responseSeries(1)->count(),
             result->candidates.at(*result->best).trace.size());
    // Both Bode plots, with their figures beside each other.
    QVERIFY(result->bodeRead && result->bodeBest);
    QCOMPARE(o.search->bode()->runCount(), 2);
    QVERIFY(o.search->bode()->magnitudePoints(1)->count() >= 4);
    auto *table = o.search->findChild<QTableWidget *>(QStringLiteral("bestVsRead"));
    const QString readBw = rowText(table, QStringLiteral("Bandwidth (-3 dB)"), 0);
    const QString bestBw = rowText(table, QStringLiteral("Bandwidth (-3 dB)"), 1);
    qInfo("bandwidth: gains read %s, suggested %s; %s", qPrintable(readBw), qPrintable(bestBw),
          qPrintable(o.search->bode()->figuresText()));
    // Each beside the other. A host loaded by a parallel build resolves fewer frequencies (a
    // bandwidth beyond them reads "not reached"): the figures' values are tst_gainsearchbode's.
    QVERIFY(!readBw.isEmpty() && !bestBw.isEmpty());
    if (readBw.endsWith(QStringLiteral(" Hz")))
        QVERIFY(readBw != bestBw);
    QVERIFY(!rowText(table, QStringLiteral("Peak"), 1).isEmpty());
    // The drive holds the gains read: the suggestion was in RAM only for its sweep.
    QVERIFY(rig.barrier());
    QVERIFY(samePid(rig.ramPid(1), before));
    QVERIFY(o.search->findChild<QPushButton *>(QStringLiteral("writeSuggestedRam"))->isEnabled());
}

void tst_GainSearchBodeView::escInTheBestsSweepRestores()
{
    SimRig rig;
    QVERIFY(rig.open());
    Opened o = openView(rig, 1);
    QVERIFY(o.view);
    const lk::protocol::PidGains before = rig.ramPid(1);
    Yes yes;
    QVERIFY(o.search->runSearch());
    // The best's sweep: its gains are in RAM and the motor turns.
    QTRY_VERIFY_WITH_TIMEOUT(o.search->statusText().startsWith(
                                 QStringLiteral("Measuring the Bode of the suggested gains")),
                             kSearchWaitMs);
    QTRY_VERIFY_WITH_TIMEOUT(!samePid(rig.ramPid(1), before) && motorOn(rig, 1), kWaitMs);
    o.view->haltLocalMotion(QStringLiteral("Emergency stop.")); // what Esc does
    QTRY_VERIFY_WITH_TIMEOUT(!o.search->isRunning(), kWaitMs);
    const QString status = o.search->statusText();
    QVERIFY2(status.startsWith(QStringLiteral("Stopped.")), qPrintable(status));
    QVERIFY2(status.contains(QStringLiteral("back in RAM")), qPrintable(status));
    QVERIFY(rig.barrier());
    QVERIFY(!motorOn(rig, 1));
    QVERIFY(samePid(rig.ramPid(1), before));
}

QTEST_MAIN(tst_GainSearchBodeView)
#include "tst_gainsearchbodeview.moc"
