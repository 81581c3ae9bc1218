// The gate of the old CAN generation's multi-motor torque frame (0x280): every drive checked as
// one torque command, the frame refused as a whole naming the drive and the limit.

#include "SafetyTestUtil.h"

#include <protocol/RequestBuilder.h>
#include <safety/MultiTorqueGuard.h>

#include <QtTest/QtTest>

using namespace lk;
using lk::test::req;
using protocol::Generation;
using protocol::Link;
using protocol::Series;
using safety::LimitKind;
using safety::MultiTorqueProblem;

Q_DECLARE_METATYPE(lk::protocol::Request)
Q_DECLARE_METATYPE(QVector<lk::protocol::Request>)
Q_DECLARE_METATYPE(lk::protocol::Link)
Q_DECLARE_METATYPE(lk::safety::LimitKind)
Q_DECLARE_METATYPE(lk::safety::MultiTorqueProblem)

namespace {
const protocol::DecodeContext kOldCan{Series::MG, Generation::V2_3, Link::Can};

protocol::Request torque(int id, double a)
{
    return req(protocol::build::torque(id, a, kOldCan));
}

/// Drives 1..4: old CAN MGs with a 2 A torque limit; drive 3 is told to be V2.36, drive 4's
/// series is unknown, drive 6 is not known at all.
safety::MultiTorqueDrive drive(int id)
{
    safety::MultiTorqueDrive d;
    if (id == 6)
        return d;
    d.generation = id == 3 ? Generation::V2_35 : Generation::V2_3;
    if (id != 4)
        d.series = Series::MG;
    d.limits = safety::SoftLimits::defaults(Series::MG);
    d.limits.maxTorqueA = 2.0;
    return d;
}
} // namespace

class tst_MultiTorqueGuard : public QObject {
    Q_OBJECT
private slots:
    void check_data();
    void check();
};

void tst_MultiTorqueGuard::check_data()
{
    QTest::addColumn<QVector<protocol::Request>>("torques");
    QTest::addColumn<Link>("link");
    QTest::addColumn<MultiTorqueProblem>("problem");
    QTest::addColumn<int>("id");
    QTest::addColumn<LimitKind>("limit");
    QTest::addColumn<QString>("words");    ///< must appear in the refusal
    QTest::addColumn<QList<int>>("onBus"); ///< the drives known to be on the bus

    using P = MultiTorqueProblem;
    const QVector<protocol::Request> two{torque(1, 1.6), torque(2, -1.6)};
    QTest::newRow("two within") << two << Link::Can << P::None << 0 << LimitKind::None << ""
                                << QList<int>{};
    QTest::newRow("at the limit") << QVector<protocol::Request>{torque(1, 2.0), torque(2, -2.0)}
                                  << Link::Can << P::None << 0 << LimitKind::None << ""
                                  << QList<int>{};
    QTest::newRow("over drive 2's torque limit")
        << QVector<protocol::Request>{torque(1, 1.0), torque(2, -2.4)} << Link::Can << P::Limit << 2
        << LimitKind::SoftTorque << "drive 2: |iq| 2.4 A is over its torque limit 2 A"
        << QList<int>{};
    QTest::newRow("unknown series")
        << QVector<protocol::Request>{torque(1, 0.5), torque(4, 0.5)} << Link::Can << P::Limit << 4
        << LimitKind::UnknownSeries << "drive 4: its series is not known" << QList<int>{};
    QTest::newRow("unknown generation")
        << QVector<protocol::Request>{torque(1, 0.5), torque(2, 0.5)} << Link::Can
        << P::UnknownGeneration << 2 << LimitKind::None
        << "drive 2: its series and CAN generation are not known" << QList<int>{};
    QTest::newRow("V2.36") << QVector<protocol::Request>{torque(3, 0.5)} << Link::Can << P::V236
                           << 3 << LimitKind::None << "drive 3 speaks CAN V2.36" << QList<int>{};
    QTest::newRow("RS485") << two << Link::Rs485 << P::NotCan << 0 << LimitKind::None
                           << "exists on CAN only" << QList<int>{};
    QTest::newRow("none") << QVector<protocol::Request>{} << Link::Can << P::NoDrive << 0
                          << LimitKind::None << "names no drive" << QList<int>{};
    QTest::newRow("five") << QVector<protocol::Request>{torque(1, 0), torque(2, 0), torque(3, 0),
                                                        torque(4, 0), torque(1, 0)}
                          << Link::Can << P::TooManyDrives << 0 << LimitKind::None << "at most 4"
                          << QList<int>{};
    QTest::newRow("ID 6") << QVector<protocol::Request>{torque(6, 0.1)} << Link::Can
                          << P::IdOutOfRange << 6 << LimitKind::None << "IDs 1..4 only"
                          << QList<int>{};
    QTest::newRow("twice") << QVector<protocol::Request>{torque(2, 0.1), torque(2, 0.2)}
                           << Link::Can << P::DuplicateId << 2 << LimitKind::None
                           << "drive 2 is named twice" << QList<int>{};
    QTest::newRow("not a torque") << QVector<protocol::Request>{req(protocol::build::speed(1, 10))}
                                  << Link::Can << P::NotTorque << 1 << LimitKind::None
                                  << "only torque" << QList<int>{};
    // An empty slot is 0 A to a drive in Broadcast Mode: a known drive must be named.
    QTest::newRow("drive 2 on the bus, not named")
        << QVector<protocol::Request>{torque(1, 0.5)} << Link::Can << P::UnnamedDrive << 2
        << LimitKind::None << "drive 2 is on the bus and would get 0 A" << QList<int>{1, 2};
    QTest::newRow("drive 2 named with 0 A")
        << QVector<protocol::Request>{torque(1, 0.5), torque(2, 0)} << Link::Can << P::None << 0
        << LimitKind::None << "" << QList<int>{1, 2};
    QTest::newRow("drive 6 beyond the frame's slots")
        << QVector<protocol::Request>{torque(1, 0.5)} << Link::Can << P::None << 0
        << LimitKind::None << "" << QList<int>{1, 6};
}

void tst_MultiTorqueGuard::check()
{
    QFETCH(QVector<protocol::Request>, torques);
    QFETCH(Link, link);
    QFETCH(MultiTorqueProblem, problem);
    QFETCH(int, id);
    QFETCH(LimitKind, limit);
    QFETCH(QString, words);
    QFETCH(QList<int>, onBus);
    // Drive 2's generation is unknown in the row that says so.
    const bool forget = QByteArray(QTest::currentDataTag()) == "unknown generation";
    const safety::MultiTorqueVerdict v = safety::MultiTorqueGuard::check(
        torques, link,
        [forget](int id) {
            safety::MultiTorqueDrive d = drive(id);
            if (forget && id == 2)
                d.generation.reset();
            return d;
        },
        QSet<int>(onBus.cbegin(), onBus.cend()));
    QCOMPARE(v.problem, problem);
    QCOMPARE(v.id, id);
    QCOMPARE(v.verdict.kind, limit);
    QCOMPARE(v.allowed(), problem == MultiTorqueProblem::None);
    const QString text = safety::MultiTorqueGuard::text(v);
    QVERIFY2(text.contains(words), qPrintable(text));
    if (!v.allowed())
        QVERIFY2(text.endsWith(QStringLiteral("nothing was sent")), qPrintable(text));
}

QTEST_APPLESS_MAIN(tst_MultiTorqueGuard)
#include "tst_multitorqueguard.moc"
