// How `lkctl monitor` assembles rows: one poll round per row (wide) or per drive and round
// (long, JSON), never mixing two rounds, stamped with the round's time; fed with samples
// directly, so that lost replies happen exactly where the test puts them.

#include <MonitorTable.h>

#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtTest/QtTest>

using lk::bus::TelemetryField;
using lk::bus::TelemetrySample;
using lk::lkctl::MonitorFormat;
using lk::lkctl::MonitorTable;
using lk::protocol::Command;
using lk::protocol::Series;

namespace {

const QVector<Command> kMix{Command::ReadState2, Command::ReadState1, Command::ReadMultiTurn};

double roundTime(int round)
{
    return round * 0.1; // the rounds of these tests begin every 100 ms
}

/// A poll reply of `round` (numbered from 1) whose values all encode the round, so that a row
/// shows which round each of its values came from: temperature = round, speed = 10 x round,
/// voltage = round + 0.5, multi-turn = 100 x round.
TelemetrySample reply(int id, Command command, int round, double offsetS, bool power = false)
{
    TelemetrySample s;
    s.id = id;
    s.source = command;
    s.cycle = quint64(round);
    s.cycleTime = roundTime(round);
    s.time = roundTime(round) + offsetS;
    switch (command) {
    case Command::ReadState2:
        s.fields = TelemetryField::Temperature | TelemetryField::Speed | TelemetryField::Encoder |
                   (power ? TelemetryField::Power : TelemetryField::IqA);
        s.temperatureC = round;
        s.speedDps = 10 * round;
        s.encoder = round;
        s.iqA = 0.0161 * round;
        s.power = round;
        break;
    case Command::ReadState1:
        s.fields =
            TelemetryField::Temperature | TelemetryField::Voltage | TelemetryField::ErrorState;
        s.temperatureC = round;
        s.voltageV = round + 0.5;
        break;
    default:
        s.fields = TelemetryField::MultiTurn;
        s.multiTurnDeg = 100 * round;
        break;
    }
    return s;
}

QList<QByteArray> feed(MonitorTable &table, const QList<TelemetrySample> &samples)
{
    QList<QByteArray> rows;
    for (const TelemetrySample &s : samples)
        rows << table.add(s);
    return rows;
}

/// Drive 3, three polls a round, rounds 1..4; in round 1 the read_state2 reply is lost, in
/// round 3 the read_state1 reply.
QList<TelemetrySample> roundsWithLosses()
{
    QList<TelemetrySample> samples;
    for (int round = 1; round <= 4; ++round) {
        if (round != 1)
            samples << reply(3, Command::ReadState2, round, 0.002);
        if (round != 3)
            samples << reply(3, Command::ReadState1, round, 0.004);
        samples << reply(3, Command::ReadMultiTurn, round, 0.006);
    }
    return samples;
}

QMap<int, std::optional<Series>> drives(std::initializer_list<std::pair<int, Series>> list)
{
    QMap<int, std::optional<Series>> m;
    for (const auto &[id, series] : list)
        m.insert(id, series);
    return m;
}

} // namespace

class tst_MonitorTable : public QObject {
    Q_OBJECT
private slots:
    void longRowsNeverMixRounds();
    void wideRowPerRound();
    void jsonRowsNeverMixRounds();
    void samplesOfNoPollAndLateOnesAreIgnored();
    void flushWritesTheOpenRound();
    void v235State1CarriesBusCurrentAndMotorState();
};

// A firmware 2.35 drive's read_state1 also brings bus current and the motor state (docs/V2.35.md
// section 5): its columns follow the voltage's; a V2.3 drive on the same bus has none.
void tst_MonitorTable::v235State1CarriesBusCurrentAndMotorState()
{
    MonitorTable table({Command::ReadState1}, drives({{3, Series::MS}, {5, Series::MF}}),
                       MonitorFormat::CsvWide, {3});
    QCOMPARE(table.header(), QByteArray("time_s,id3_temperature_c,id3_voltage_v,id3_error_state,"
                                        "id3_bus_current_a,id3_motor_on,id5_temperature_c,"
                                        "id5_voltage_v,id5_error_state\n"));
    lk::protocol::State1 s1;
    s1.generation = lk::protocol::Generation::V2_35;
    s1.voltageRaw = 2400;
    s1.busCurrentRaw = 125;
    s1.motorStateRaw = 0x10;
    TelemetrySample s = TelemetrySample::fromState1(3, s1, 0.5);
    s.cycle = 1;
    s.cycleTime = 0.5;
    QVERIFY(table.add(s).isEmpty());
    const QList<QByteArray> rows = table.flush();
    QCOMPARE(rows.size(), 1);
    QCOMPARE(rows.first(), QByteArray("0.500000,0,24.00,0,1.25,0,,,\n"));
}

void tst_MonitorTable::longRowsNeverMixRounds()
{
    MonitorTable table(kMix, drives({{3, Series::MF}}), MonitorFormat::CsvLong);
    QCOMPARE(table.header(), QByteArray("time_s,id,temperature_c,voltage_v,error_state,iq_a,"
                                        "speed_dps,encoder,multi_turn_deg\n"));
    const QList<QByteArray> rows = feed(table, roundsWithLosses()) + table.flush();
    for (int i = 0; i < rows.size(); ++i) {
        const QList<QByteArray> cells = rows.at(i).trimmed().split(',');
        QCOMPARE(cells.size(), 9);
        // Every value of the row is of one round, and the row has that round's time.
        const int round = int(cells.at(8).toDouble() / 100); // multi-turn: never lost here
        QCOMPARE(cells.at(0), QByteArray::number(roundTime(round), 'f', 6));
        QCOMPARE(cells.at(1), QByteArray("3"));
        QCOMPARE(cells.at(2), QByteArray::number(round)); // temperature: from state1 or state2
        QCOMPARE(cells.at(3), round == 3 ? QByteArray() : QByteArray::number(round + 0.5, 'f', 2));
        QCOMPARE(cells.at(6), round == 1 ? QByteArray() : QByteArray::number(10 * round));
        QCOMPARE(round, i + 1);
    }
    QCOMPARE(rows.size(), 4);
}

void tst_MonitorTable::wideRowPerRound()
{
    MonitorTable table(kMix, drives({{17, Series::MS}, {3, Series::MF}}), MonitorFormat::CsvWide);
    QCOMPARE(table.header(),
             QByteArray("time_s,id3_temperature_c,id3_voltage_v,id3_error_state,id3_iq_a,"
                        "id3_speed_dps,id3_encoder,id3_multi_turn_deg,id17_temperature_c,"
                        "id17_voltage_v,id17_error_state,id17_power,id17_speed_dps,id17_encoder,"
                        "id17_multi_turn_deg\n"));
    QList<TelemetrySample> samples;
    for (int round = 1; round <= 3; ++round) {
        for (int id : {3, 17}) {
            for (Command c : kMix) {
                if (!(round == 2 && id == 17 && c == Command::ReadState2)) // lost
                    samples << reply(id, c, round, 0.001 * id, id == 17);
            }
        }
    }
    const QList<QByteArray> rows = feed(table, samples);
    QCOMPARE(rows.size(), 3); // every round complete but the lossy one, written at round 3
    QCOMPARE(rows.at(0),
             QByteArray("0.100000,1,1.50,0,0.0161,10,1,100.00,1,1.50,0,1,10,1,100.00\n"));
    QCOMPARE(rows.at(1), QByteArray("0.200000,2,2.50,0,0.0322,20,2,200.00,2,2.50,0,,,,200.00\n"));
}

void tst_MonitorTable::jsonRowsNeverMixRounds()
{
    MonitorTable table(kMix, drives({{3, Series::MF}}), MonitorFormat::Json);
    QCOMPARE(table.header(), QByteArray());
    const QList<QByteArray> rows = feed(table, roundsWithLosses()) + table.flush();
    QCOMPARE(rows.size(), 4);
    for (int i = 0; i < rows.size(); ++i) {
        const int round = i + 1;
        const QJsonObject o = QJsonDocument::fromJson(rows.at(i)).object();
        QCOMPARE(o.value("time_s").toDouble(), roundTime(round));
        QCOMPARE(o.value("temperature_c").toInt(), round);
        QCOMPARE(o.value("multi_turn_deg").toDouble(), 100.0 * round);
        QCOMPARE(o.contains("speed_dps"), round != 1); // lost: no key, not 0
        QCOMPARE(o.contains("voltage_v"), round != 3);
    }
}

void tst_MonitorTable::samplesOfNoPollAndLateOnesAreIgnored()
{
    MonitorTable table(kMix, drives({{3, Series::MF}}), MonitorFormat::CsvLong);
    TelemetrySample operatorRead = reply(3, Command::ReadState2, 1, 0.001);
    operatorRead.cycle = 0; // e.g. lkctl's identification before polling
    QVERIFY(table.add(operatorRead).isEmpty());
    QList<QByteArray> rows;
    for (Command c : kMix)
        rows << table.add(reply(3, c, 2, 0.01));
    QCOMPARE(rows.size(), 1);
    QVERIFY(table.add(reply(3, Command::ReadState1, 2, 0.05)).isEmpty()); // round 2 is written
    QVERIFY(table.add(reply(3, Command::ReadState1, 1, 0.05)).isEmpty()); // older still
    QVERIFY(table.flush().isEmpty());
}

void tst_MonitorTable::flushWritesTheOpenRound()
{
    MonitorTable table(kMix, drives({{3, Series::MF}}), MonitorFormat::CsvWide);
    QVERIFY(table.add(reply(3, Command::ReadState2, 5, 0.002)).isEmpty());
    const QList<QByteArray> rows = table.flush();
    QCOMPARE(rows, QList<QByteArray>{"0.500000,5,,,0.0805,50,5,\n"});
    QCOMPARE(table.elapsedS(), 0.0);
}

QTEST_APPLESS_MAIN(tst_MonitorTable)
#include "tst_monitortable.moc"
