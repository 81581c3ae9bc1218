#include "FaultInjector.h"

#include "protocol/Checksum.h"
#include "protocol/Frame.h"

#include <QtCore/QStringList>

#include <optional>

namespace lk::sim {

namespace {
constexpr int kMaxGarbage = 8;

struct ProbabilityKey {
    const char *key;
    Fault fault;
};
constexpr ProbabilityKey kProbabilityKeys[] = {
    {"drop", Fault::DropReply},  {"corrupt", Fault::CorruptReply}, {"length", Fault::WrongLength},
    {"garbage", Fault::Garbage}, {"delay", Fault::ExtraDelay},
};

std::optional<Fault> probabilityKey(const QString &key)
{
    for (const auto &k : kProbabilityKeys) {
        if (key == QLatin1String(k.key))
            return k.fault;
    }
    return std::nullopt;
}
} // namespace

FaultInjector::FaultInjector(quint32 seed) : m_rng(seed) {}

void FaultInjector::setProbability(Fault fault, double probability)
{
    m_probability[index(fault)] = qBound(0.0, probability, 1.0);
}

void FaultInjector::injectNext(Fault fault, int count)
{
    if (count > 0)
        m_oneShot[index(fault)] += count;
}

void FaultInjector::dropNextRepliesTo(quint8 command, int id, int count)
{
    if (count <= 0)
        return;
    for (AimedDrop &d : m_aimedDrops) {
        if (d.command == command && d.id == id) {
            d.count += count;
            return;
        }
    }
    m_aimedDrops.append({command, id, count});
}

int FaultInjector::pendingAimedDrops() const
{
    int n = 0;
    for (const AimedDrop &d : m_aimedDrops)
        n += d.count;
    return n;
}

bool FaultInjector::firesAimedDrop(const QByteArray &reply)
{
    const auto command = static_cast<quint8>(reply[1]);
    const auto id = static_cast<quint8>(reply[2]);
    for (qsizetype i = 0; i < m_aimedDrops.size(); ++i) {
        AimedDrop &d = m_aimedDrops[i];
        if (d.command != command || (d.id != 0 && d.id != id))
            continue;
        if (--d.count == 0)
            m_aimedDrops.removeAt(i);
        ++m_count[index(Fault::DropReply)];
        return true;
    }
    return false;
}

void FaultInjector::setSilenced(int id, bool silenced)
{
    if (silenced)
        m_silenced.insert(id);
    else
        m_silenced.remove(id);
}

void FaultInjector::clear()
{
    m_probability.fill(0);
    m_oneShot.fill(0);
    m_aimedDrops.clear();
    m_silenced.clear();
}

bool FaultInjector::active() const
{
    for (int i = 0; i < kFaultKinds; ++i) {
        if (m_probability[i] > 0 || m_oneShot[i] > 0)
            return true;
    }
    return !m_silenced.isEmpty() || !m_aimedDrops.isEmpty();
}

bool FaultInjector::fires(Fault fault)
{
    int &shots = m_oneShot[index(fault)];
    bool hit = false;
    if (shots > 0) {
        --shots;
        hit = true;
    } else {
        const double p = m_probability[index(fault)];
        // Draw only when needed, so that enabling one fault does not reshuffle the others.
        hit = p > 0 && m_rng.generateDouble() < p;
    }
    if (hit)
        ++m_count[index(fault)];
    return hit;
}

bool FaultInjector::apply(QByteArray &reply, double &extraDelay)
{
    if (reply.size() < protocol::kHeaderSize)
        return true;
    if (firesAimedDrop(reply) || fires(Fault::DropReply))
        return false;
    if (fires(Fault::WrongLength))
        shorten(reply);
    else if (fires(Fault::CorruptReply))
        corrupt(reply);
    if (fires(Fault::Garbage))
        reply.prepend(garbage());
    if (fires(Fault::ExtraDelay))
        extraDelay += m_extraDelay;
    return true;
}

bool FaultInjector::applyFirmwareChecksumBug(QByteArray &reply)
{
    if (reply.size() <= protocol::kHeaderSize || !fires(Fault::FirmwareChecksum))
        return false;
    // The captured bad frames were off by +3 or -3 from the right sum (docs/V2.35.md section 12).
    const int offset = m_rng.bounded(2) ? 3 : -3;
    reply[reply.size() - 1] = static_cast<char>(static_cast<quint8>(reply.back()) + offset);
    return true;
}

void FaultInjector::corrupt(QByteArray &reply)
{
    const int len = static_cast<quint8>(reply[3]);
    // XOR with a non-zero value always changes the byte sum, so the checksum must fail.
    const auto flip = static_cast<char>(1 + m_rng.bounded(255));
    const qsizetype at =
        len > 0 ? protocol::kHeaderSize + static_cast<qsizetype>(m_rng.bounded(len)) : 4;
    if (at < reply.size())
        reply[at] = static_cast<char>(reply[at] ^ flip);
}

void FaultInjector::shorten(QByteArray &reply)
{
    // Checksums stay valid, so the host sees a LEN the command never carries (bad_length).
    const auto cmd = static_cast<quint8>(reply[1]);
    const auto id = static_cast<quint8>(reply[2]);
    const int len = static_cast<quint8>(reply[3]);
    QByteArray data = reply.mid(protocol::kHeaderSize, len);
    if (len > 0)
        data.chop(1);
    else
        data.append('\0');
    reply = protocol::encodeFrame(cmd, id, data);
}

QByteArray FaultInjector::garbage()
{
    QByteArray g;
    const int n = 1 + static_cast<int>(m_rng.bounded(kMaxGarbage));
    for (int i = 0; i < n; ++i) {
        // Never the frame head: noise that imitates a header would also eat the real reply,
        // which is a different fault (and one a seeded test could not rely on).
        auto b = static_cast<quint8>(m_rng.bounded(255));
        if (b >= protocol::kFrameHead)
            ++b;
        g.append(static_cast<char>(b));
    }
    return g;
}

bool FaultInjector::configure(const QString &spec, QString *error)
{
    auto fail = [error](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    std::array<double, kFaultKinds> probability = m_probability;
    std::array<int, kFaultKinds> next{};
    double delay = m_extraDelay;
    QSet<int> silenced = m_silenced;
    std::optional<quint32> seed;
    const QStringList items = spec.split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const QString &raw : items) {
        const QString item = raw.trimmed();
        const QString key = item.section(QLatin1Char('='), 0, 0).trimmed().toLower();
        const QString value = item.section(QLatin1Char('='), 1).trimmed();
        bool ok = false;
        if (const auto fault = probabilityKey(key)) {
            const double p = value.toDouble(&ok);
            if (!ok || p < 0 || p > 1)
                return fail(QStringLiteral("fault '%1' needs a probability 0..1, got '%2'")
                                .arg(key, value));
            probability[index(*fault)] = p;
        } else if (const auto once = key.endsWith(QLatin1String("_next"))
                                         ? probabilityKey(key.chopped(5))
                                         : std::nullopt) {
            // "drop_next=1": exactly the next reply, for tests of one lost reply.
            const int n = value.toInt(&ok);
            if (!ok || n < 0 || n > 1000000)
                return fail(QStringLiteral("fault '%1' needs a count 0..1000000, got '%2'")
                                .arg(key, value));
            next[index(*once)] += n;
        } else if (key == QLatin1String("delay_ms")) {
            const double ms = value.toDouble(&ok);
            if (!ok || ms < 0 || ms > 10000)
                return fail(QStringLiteral("delay_ms must be 0..10000, got '%1'").arg(value));
            delay = ms / 1000.0;
        } else if (key == QLatin1String("silent")) {
            const int id = value.toInt(&ok);
            if (!ok || id < protocol::kMinId || id > protocol::kMaxId)
                return fail(QStringLiteral("silent needs an ID 1..32, got '%1'").arg(value));
            silenced.insert(id);
        } else if (key == QLatin1String("seed")) {
            const uint s = value.toUInt(&ok);
            if (!ok)
                return fail(
                    QStringLiteral("seed must be an unsigned integer, got '%1'").arg(value));
            seed = s;
        } else {
            return fail(QStringLiteral("unknown fault '%1' (expected drop, corrupt, length, "
                                       "garbage, delay, one of those with _next, delay_ms, "
                                       "silent or seed)")
                            .arg(key));
        }
    }
    m_probability = probability;
    for (int i = 0; i < kFaultKinds; ++i)
        m_oneShot[i] += next[i];
    m_extraDelay = delay;
    m_silenced = silenced;
    if (seed)
        setSeed(*seed);
    return true;
}

} // namespace lk::sim
