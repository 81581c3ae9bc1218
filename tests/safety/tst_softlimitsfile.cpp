// Limits files and stored limits: whatever is wrong is refused with the key named; nothing
// falls back silently.

#include <protocol/RequestBuilder.h>
#include <safety/JsonKeyCheck.h>
#include <safety/MotionGuard.h>
#include <safety/SoftLimits.h>

#include <QtTest/QtTest>

using namespace lk;

class tst_SoftLimitsFile : public QObject {
    Q_OBJECT
private slots:
    void refused_data();
    void refused();
    void accepted();
    void duplicateKeyFinder();
    void speedLimitAlwaysExists();
};

void tst_SoftLimitsFile::refused_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("named");
    QTest::newRow("misspelt key") << QByteArray(R"({"max_speed": 720})")
                                  << QStringLiteral("unknown key \"max_speed\"");
    QTest::newRow("duplicate key") << QByteArray(R"({"max_speed_dps": 720, "max_speed_dps": 5000})")
                                   << QStringLiteral("\"max_speed_dps\" is given twice");
    QTest::newRow("escaped duplicate") << QByteArray(R"({"max_power": 10, "max_po\u0077er": 20})")
                                       << QStringLiteral("\"max_power\" is given twice");
    QTest::newRow("wrong type") << QByteArray(R"({"max_speed_dps": "fast"})")
                                << QStringLiteral("max_speed_dps must be a number in 0.01..18000 "
                                                  "dps (got \"fast\")");
    QTest::newRow("negative") << QByteArray(R"({"max_torque_a": -1})")
                              << QStringLiteral("max_torque_a must be a number in 0..32 A");
    QTest::newRow("zero speed") << QByteArray(R"({"max_speed_dps": 0})")
                                << QStringLiteral("max_speed_dps must be a number in 0.01..");
    QTest::newRow("too fast") << QByteArray(R"({"max_speed_dps": 1e6})")
                              << QStringLiteral("(got 1000000)");
    QTest::newRow("infinite") << QByteArray(R"({"max_speed_dps": 1e999})")
                              << QStringLiteral("illegal number");
    QTest::newRow("fractional power") << QByteArray(R"({"max_power": 2.5})")
                                      << QStringLiteral("max_power must be a whole number in "
                                                        "0..1000");
    QTest::newRow("null speed") << QByteArray(R"({"max_speed_dps": null})")
                                << QStringLiteral("(got null)");
    QTest::newRow("range upside down")
        << QByteArray(R"({"min_angle_deg": 10, "max_angle_deg": -10})")
        << QStringLiteral("min_angle_deg (10) must not exceed max_angle_deg (-10)");
    QTest::newRow("array") << QByteArray("[1]") << QStringLiteral("not a JSON object");
    QTest::newRow("broken") << QByteArray(R"({"max_power": )")
                            << QStringLiteral("not a JSON object (");
}

void tst_SoftLimitsFile::refused()
{
    QFETCH(QByteArray, text);
    QFETCH(QString, named);
    QString error;
    QVERIFY(!safety::SoftLimits::fromJsonText(text, safety::SoftLimits{}, &error));
    QVERIFY2(error.contains(named), qPrintable(error));
}

void tst_SoftLimitsFile::accepted()
{
    QString error;
    const auto l = safety::SoftLimits::fromJsonText(
        R"({"max_speed_dps": 720, "max_power": 300, "min_angle_deg": null,
            "nested": 1})",
        safety::SoftLimits{}, &error);
    QVERIFY(!l); // "nested" is unknown
    const auto ok = safety::SoftLimits::fromJsonText(
        R"({"max_speed_dps": 720, "max_power": 300, "max_angle_deg": 90})", safety::SoftLimits{},
        &error);
    QVERIFY2(ok, qPrintable(error));
    QCOMPARE(ok->maxSpeedDps, 720.0);
    QCOMPARE(ok->maxPower, 300);
    QCOMPARE(ok->maxAngleDeg, std::optional<double>(90));
    QCOMPARE(ok->maxTorqueA, safety::SoftLimits{}.maxTorqueA);
}

void tst_SoftLimitsFile::duplicateKeyFinder()
{
    using safety::JsonKeyCheck;
    // Nested keys and strings in arrays are not top-level keys; a quoted "a" inside a value is
    // no key either.
    const QByteArray nested = "{\"a\": {\"b\": 1, \"b\": 2}, \"c\": [ \"a\" ]}";
    QCOMPARE(JsonKeyCheck::duplicateKey(nested), std::nullopt);
    const QByteArray twice = "{\"a\": \"x\\\",\\\"a\", \"b\": 1, \"a\": 2}";
    QCOMPARE(JsonKeyCheck::duplicateKey(twice), std::optional<QString>(QStringLiteral("a")));
}

void tst_SoftLimitsFile::speedLimitAlwaysExists()
{
    QVERIFY(safety::SoftLimits{}.maxSpeedDps > 0);
    QCOMPARE(safety::SoftLimits{}.maxSpeedDps, safety::MotionGuard::topSpeedDps(std::nullopt));
    safety::SoftLimits none;
    none.maxSpeedDps = 0; // no limit at all is refused, never read as "any speed"
    QVERIFY(!safety::MotionGuard::check(*protocol::build::speed(1, 10).request, std::nullopt, none)
                 .allowed());
}

QTEST_GUILESS_MAIN(tst_SoftLimitsFile)
#include "tst_softlimitsfile.moc"
