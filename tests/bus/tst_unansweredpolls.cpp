#include <bus/UnansweredPolls.h>

#include <QtTest/QTest>

using lk::bus::UnansweredPolls;
using lk::protocol::Command;

/// Which polls a drive leaves unanswered while answering its others (0x9D on an MS whose
/// series is not known): muted after kMisses in a row, never for a silent drive.
class tst_UnansweredPolls : public QObject {
    Q_OBJECT
private slots:
    void mutedAfterMissesWhileOthersAnswer();
    void silentDriveIsNeverMuted();
    void commandEverySeriesAnswersIsNeverMuted();
    void anAnswerStartsTheCountAgain();
    void clearForgets();
};

void tst_UnansweredPolls::mutedAfterMissesWhileOthersAnswer()
{
    UnansweredPolls u;
    QVERIFY(UnansweredPolls::someSeriesLacks(Command::ReadState3));
    int mutedAt = 0;
    for (int round = 1; round <= UnansweredPolls::kMisses && mutedAt == 0; ++round) {
        QVERIFY(!u.noteResult(3, Command::ReadState1, true));
        QVERIFY(!u.noteResult(3, Command::ReadState2, true));
        if (u.noteResult(3, Command::ReadState3, false))
            mutedAt = round;
    }
    QCOMPARE(mutedAt, UnansweredPolls::kMisses);
    QVERIFY(u.isMuted(3, Command::ReadState3));
    QVERIFY(!u.isMuted(3, Command::ReadState2));
    QVERIFY(!u.isMuted(4, Command::ReadState3));           // another drive is its own case
    QVERIFY(!u.noteResult(3, Command::ReadState3, false)); // said once
}

void tst_UnansweredPolls::silentDriveIsNeverMuted()
{
    // Cut off or powered down: nothing it is asked is answered. Its polls go on (it is
    // reported silent, and comes back by itself), never muted one by one.
    UnansweredPolls u;
    for (int round = 0; round < 10; ++round) {
        for (Command c : {Command::ReadState1, Command::ReadState2, Command::ReadState3})
            QVERIFY(!u.noteResult(5, c, false));
    }
    QVERIFY(u.isEmpty());
}

void tst_UnansweredPolls::commandEverySeriesAnswersIsNeverMuted()
{
    // read_state2 carries the speed the speed watch lives on: a drive that answers state1
    // but not state2 is a fault to see, not a series to learn.
    UnansweredPolls u;
    QVERIFY(!UnansweredPolls::someSeriesLacks(Command::ReadState2));
    for (int round = 0; round < 10; ++round) {
        u.noteResult(2, Command::ReadState1, true);
        QVERIFY(!u.noteResult(2, Command::ReadState2, false));
    }
    QVERIFY(!u.isMuted(2, Command::ReadState2));
}

void tst_UnansweredPolls::anAnswerStartsTheCountAgain()
{
    // A lost reply now and then (noise) is not a missing command.
    UnansweredPolls u;
    for (int round = 0; round < 20; ++round) {
        u.noteResult(1, Command::ReadState1, true);
        // kMisses - 1 lost, then one answered, again and again
        const bool answered = round % UnansweredPolls::kMisses == UnansweredPolls::kMisses - 1;
        QVERIFY(!u.noteResult(1, Command::ReadState3, answered));
    }
    QVERIFY(!u.isMuted(1, Command::ReadState3));
}

void tst_UnansweredPolls::clearForgets()
{
    UnansweredPolls u;
    for (int round = 0; round < UnansweredPolls::kMisses; ++round) {
        u.noteResult(1, Command::ReadState1, true);
        u.noteResult(1, Command::ReadState3, false);
    }
    QVERIFY(u.isMuted(1, Command::ReadState3));
    u.clear();
    QVERIFY(!u.isMuted(1, Command::ReadState3));
    QVERIFY(u.isEmpty());
}

QTEST_APPLESS_MAIN(tst_UnansweredPolls)
#include "tst_unansweredpolls.moc"
