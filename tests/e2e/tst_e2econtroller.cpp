#include "E2eUtil.h"

#include <protocol/FieldJson.h>
#include <protocol/OrderedJson.h>
#include <protocol/Reply.h>
#include <protocol/Request.h>
#include <protocol/StreamParser.h>

#include <QtCore/QElapsedTimer>
#include <QtCore/QFile>
#include <QtCore/QFileInfo>
#include <QtCore/QRegularExpression>
#include <QtCore/QTemporaryDir>
#include <QtSerialPort/QSerialPort>
#include <QtTest/QTest>

using namespace lk;
using namespace lk::e2e;
using protocol::OrderedJson;

namespace {

constexpr int kBaud = 115200;

/// One request seen on the tap and what followed it up to the next request.
struct Observed {
    protocol::Request request;
    std::optional<protocol::Reply> reply; ///< a valid reply for its ID and command
    bool spoilt = false;   ///< bytes after the request that are no valid reply (or a wrong one)
    bool anyReply = false; ///< any bytes at all came after the request
    int noiseBytes = 0;    ///< garbage before the reply
};

/// The decode context of each drive of the bus the test serves (1:MF, 2:MS, 3:MG4010@2.35).
protocol::DecodeContext contextOf(int id)
{
    using protocol::Generation;
    using protocol::Series;
    if (id == 2)
        return {Series::MS, Generation::V2_3};
    if (id == 3)
        return {Series::MG, Generation::V2_35};
    return {Series::MF, Generation::V2_3};
}

/// Cut the tap's bytes into requests and what followed each, as a listen-only monitor would.
QList<Observed> observe(const QByteArray &stream)
{
    QList<Observed> out;
    const auto sink = [&out](const protocol::ParseEvent &e) {
        if (e.isFrame && e.direction == protocol::FrameDirection::Request) {
            if (const auto r = protocol::decodeRequest(e.frame).request) {
                out.append(Observed{*r, std::nullopt, false, false, 0});
                return;
            }
        }
        if (out.isEmpty())
            return; // before the first request: the stream may begin inside a frame
        Observed &o = out.last();
        o.anyReply = true;
        if (!e.isFrame) {
            if (!o.reply && !o.spoilt && e.error == protocol::ParseError::Garbage)
                o.noiseBytes += int(e.bytes.size());
            else
                o.spoilt = true;
            return;
        }
        const auto d = protocol::decodeReply(e.frame, contextOf(o.request.id));
        if (o.reply || !d.reply || d.reply->id != o.request.id ||
            d.reply->command != o.request.command)
            o.spoilt = true;
        else
            o.reply = d.reply;
    };
    protocol::StreamParser parser;
    parser.feed(stream, sink);
    return out;
}

QList<QJsonObject> readLog(const QString &path)
{
    QFile f(path);
    QList<QJsonObject> out;
    if (!f.open(QIODevice::ReadOnly))
        return out;
    for (const QByteArray &line : f.readAll().split('\n')) {
        if (!line.isEmpty())
            out.append(QJsonDocument::fromJson(line).object());
    }
    return out;
}

QByteArray fieldsText(const QJsonValue &v)
{
    return OrderedJson::fieldsText(v.toObject());
}

bool sameRequest(const Observed &o, const QJsonObject &logged)
{
    return logged.value(QStringLiteral("id")).toInt() == o.request.id &&
           logged.value(QStringLiteral("code")).toString() ==
               protocol::CommandTable::codeText(static_cast<quint8>(o.request.command)) &&
           fieldsText(logged.value(QStringLiteral("request"))) ==
               OrderedJson::fieldsText(
                   protocol::FieldJson::requestFields(o.request, contextOf(o.request.id)));
}

/// Empty when what the tap carried agrees with the logged outcome, else why not.
QString disagreement(const Observed &o, const QJsonObject &logged)
{
    if (!sameRequest(o, logged))
        return QStringLiteral("another request");
    const QString outcome = logged.value(QStringLiteral("outcome")).toString();
    if (outcome == QLatin1String("answered")) {
        if (!o.reply || o.spoilt)
            return QStringLiteral("no valid reply on the tap");
        if (fieldsText(logged.value(QStringLiteral("reply"))) !=
            OrderedJson::fieldsText(protocol::FieldJson::replyFields(*o.reply)))
            return QStringLiteral("other reply values");
        if (logged.value(QStringLiteral("noise_bytes")).toInt() != o.noiseBytes)
            return QStringLiteral("other noise");
        return {};
    }
    if (outcome == QLatin1String("unanswered") || outcome == QLatin1String("dropped"))
        return o.anyReply ? QStringLiteral("bytes after an unanswered request") : QString();
    if (outcome == QLatin1String("garbled"))
        return o.spoilt && !o.reply ? QString() : QStringLiteral("a garbled reply decoded");
    return QStringLiteral("outcome %1 on a tap nobody else wrote to").arg(outcome);
}

} // namespace

/// lksim --controller on a pty, read through a real QSerialPort opened read-only, as the
/// listen-only monitor will: the tap carries each logged request and its reply in bus order,
/// with the values of the ground-truth log, faults included; bytes written to the pty are a
/// second master that collides.
class tst_E2eController : public QObject {
    Q_OBJECT
private slots:
    void tapMatchesLog();
    void secondMasterCollides();
    void nobodyReadingDoesNotStallTheBus();
};

void tst_E2eController::tapMatchesLog()
{
    QTemporaryDir dir;
    const QString logPath = dir.filePath(QStringLiteral("truth.jsonl"));
    LksimProcess sim(QStringLiteral(LKSIM_PATH));
    QVERIFY2(
        sim.start({QStringLiteral("--motors"), QStringLiteral("1:MF,2:MS,3:MG4010@2.35"),
                   QStringLiteral("--baud"), QString::number(kBaud), QStringLiteral("--controller"),
                   QStringLiteral("rate=400,ids=1-4,poll=9c:9a:92,speed=sine:300dps:2Hz,"
                                  "move=every:0.5s"),
                   QStringLiteral("--controller-log"), logPath, QStringLiteral("--faults"),
                   QStringLiteral("drop=0.03,garbage=0.03,corrupt=0.02,seed=5")}),
        qPrintable(sim.errorString()));

    QSerialPort port(sim.devicePath());
    port.setBaudRate(kBaud);
    QVERIFY2(port.open(QIODevice::ReadOnly), qPrintable(port.errorString()));
    QByteArray stream;
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < 2000) {
        port.waitForReadyRead(50);
        stream += port.readAll();
    }
    port.close();
    sim.stop();

    const QList<Observed> seen = observe(stream);
    const QList<QJsonObject> truth = readLog(logPath);
    QVERIFY2(seen.size() > 300, qPrintable(QString::number(seen.size())));
    QVERIFY2(truth.size() > 300, qPrintable(QString::number(truth.size())));
    // Align the tap with the log on the second request seen (the first may be cut), then
    // every request after it must be the log's next one, up to the log's end.
    qsizetype at = 0;
    while (at < truth.size() &&
           !(sameRequest(seen[1], truth[at]) && sameRequest(seen[2], truth[at + 1]) &&
             sameRequest(seen[3], truth[at + 2])))
        ++at;
    QVERIFY2(at < truth.size(), "the tap's requests are not in the log");
    QHash<QString, int> outcomes;
    int matched = 0;
    bool v235State1 = false;
    for (qsizetype i = 1; i < seen.size() && at + i - 1 < truth.size(); ++i) {
        const QJsonObject &logged = truth[at + i - 1];
        if (i == seen.size() - 1 && !seen[i].reply)
            break; // the tap closed after the last request, before its reply was whole
        const QString why = disagreement(seen[i], logged);
        QVERIFY2(why.isEmpty(),
                 qPrintable(QStringLiteral("tap request %1, log line %2: %3: %4")
                                .arg(i)
                                .arg(at + i)
                                .arg(why, QString::fromUtf8(QJsonDocument(logged).toJson(
                                              QJsonDocument::Compact)))));
        ++outcomes[logged.value(QStringLiteral("outcome")).toString()];
        ++matched;
        v235State1 |=
            logged.value(QStringLiteral("id")).toInt() == 3 &&
            logged.value(QStringLiteral("command")).toString() == QLatin1String("read_state1") &&
            logged.value(QStringLiteral("reply")).toObject().contains(QStringLiteral("motor_on"));
    }
    QVERIFY2(matched > 300, qPrintable(QString::number(matched)));
    QVERIFY(outcomes.value(QStringLiteral("answered")) > 200);
    QVERIFY(outcomes.value(QStringLiteral("unanswered")) > 0); // ID 4 is not on the bus
    QVERIFY(outcomes.value(QStringLiteral("dropped")) > 0);
    QVERIFY(outcomes.value(QStringLiteral("garbled")) > 0);
    QVERIFY(v235State1); // the V2.35 drive's read_state1 layout, beside V2.3 drives
}

void tst_E2eController::secondMasterCollides()
{
    QTemporaryDir dir;
    const QString logPath = dir.filePath(QStringLiteral("truth.jsonl"));
    LksimProcess sim(QStringLiteral(LKSIM_PATH));
    QVERIFY2(sim.start({QStringLiteral("--motors"), QStringLiteral("1:MF"),
                        QStringLiteral("--controller"), QStringLiteral("rate=max,poll=9c:9a"),
                        QStringLiteral("--controller-log"), logPath}),
             qPrintable(sim.errorString()));
    QSerialPort port(sim.devicePath());
    port.setBaudRate(kBaud);
    QVERIFY2(port.open(QIODevice::ReadWrite), qPrintable(port.errorString()));
    // 60 bytes take 5.2 ms on the wire: longer than a whole transaction of a controller that
    // sends back to back, so they must overlap one.
    port.write(QByteArray(60, '\x55'));
    QVERIFY(port.waitForBytesWritten(5000));
    QTest::qWait(300);
    port.close();
    sim.stop();
    const std::optional<LksimCounters> c = sim.counters();
    QVERIFY(c);
    QVERIFY2(c->collisions >= 1, sim.log().constData()); // more if the pty split the bytes

    QVERIFY2(sim.log().contains("lksim: second master: 60 bytes"), sim.log().constData());
    int collided = 0;
    for (const QJsonObject &o : readLog(logPath))
        collided += o.value(QStringLiteral("outcome")).toString() == QLatin1String("collided");
    QVERIFY(collided >= 1);
}

void tst_E2eController::nobodyReadingDoesNotStallTheBus()
{
    QTemporaryDir dir;
    const QString logPath = dir.filePath(QStringLiteral("truth.jsonl"));
    LksimProcess sim(QStringLiteral(LKSIM_PATH));
    QVERIFY2(
        sim.start({QStringLiteral("--motors"), QStringLiteral("1:MF"), QStringLiteral("--baud"),
                   QStringLiteral("4000000"), QStringLiteral("--controller"),
                   QStringLiteral("rate=max"), QStringLiteral("--controller-log"), logPath}),
        qPrintable(sim.errorString()));
    // About 3000 transactions a second of 18 bytes on the wire (log lines of some 190 bytes):
    // the pty's buffer (tens of KiB) is full long before 1.5 MB of log. lksim must go on,
    // discarding what nobody read, not block.
    const auto logSize = [&logPath] { return QFileInfo(logPath).size(); };
    QVERIFY(QTest::qWaitFor([&] { return logSize() > 1500000; }, 60000));
    const qint64 before = logSize();
    QTest::qWait(500);
    QVERIFY2(logSize() > before, "lksim stopped serving while nobody read the pty");
    // A reader that comes now gets current traffic.
    QSerialPort port(sim.devicePath());
    QVERIFY2(port.open(QIODevice::ReadOnly), qPrintable(port.errorString()));
    QVERIFY(port.waitForReadyRead(5000));
    port.close();
    sim.stop();
    const QRegularExpressionMatch m =
        QRegularExpression(QStringLiteral("; (\\d+) bytes of the tap discarded unread"))
            .match(QString::fromUtf8(sim.log()));
    QVERIFY2(m.hasMatch() && m.captured(1).toLongLong() > 0, sim.log().constData());
}

QTEST_GUILESS_MAIN(tst_E2eController)
#include "tst_e2econtroller.moc"
