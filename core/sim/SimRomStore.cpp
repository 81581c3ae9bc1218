#include "SimRomStore.h"

#include "SimLog.h"

#include <system/AtomicFile.h>
#include <system/BoundedFile.h>

#include <QtCore/QDir>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtCore/QRegularExpression>

#include <limits>

namespace lk::sim {

namespace {
constexpr int kFormatVersion = 1;
const char *const kFormatName = "lk-sim-rom";
constexpr qint64 kMaxFileSize = 64 * 1024; // a ROM file is a few hundred bytes

const char *const kPidKeys[] = {"angle_kp", "angle_ki", "speed_kp", "speed_ki", "iq_kp", "iq_ki"};

quint8 *pidField(protocol::PidGains &g, int i)
{
    quint8 *fields[] = {&g.angleKp, &g.angleKi, &g.speedKp, &g.speedKi, &g.iqKp, &g.iqKi};
    return fields[i];
}

// Reads an integer member within [lo, hi]; false when missing, fractional or out of range.
bool readInt(const QJsonObject &o, const char *key, qint64 lo, qint64 hi, qint64 *out)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (!v.isDouble())
        return false;
    const double d = v.toDouble();
    if (d != static_cast<double>(static_cast<qint64>(d)) || d < lo || d > hi)
        return false;
    *out = static_cast<qint64>(d);
    return true;
}

QJsonObject toJson(int id, protocol::Series series, const SimRom &rom)
{
    QJsonObject pid;
    protocol::PidGains g = rom.pid;
    for (int i = 0; i < 6; ++i)
        pid.insert(QLatin1String(kPidKeys[i]), *pidField(g, i));
    QJsonObject o;
    o.insert(QStringLiteral("format"), QLatin1String(kFormatName));
    o.insert(QStringLiteral("version"), kFormatVersion);
    o.insert(QStringLiteral("id"), id);
    o.insert(QStringLiteral("series"), protocol::seriesName(series));
    o.insert(QStringLiteral("pid"), pid);
    o.insert(QStringLiteral("accel_dps2"), rom.accelDps2);
    o.insert(QStringLiteral("encoder_zero"), rom.encoderZero);
    // The V2.35 parameter table, one entry per ParamID: its six value bytes as hex.
    QJsonObject params;
    for (const protocol::ParamInfo &info : protocol::ParamTable::all()) {
        const auto v = rom.params.read(static_cast<quint8>(info.id));
        QByteArray bytes;
        for (quint8 b : v->bytes)
            bytes.append(char(b));
        params.insert(QLatin1String(info.name), QString::fromLatin1(bytes.toHex()));
    }
    o.insert(QStringLiteral("params"), params);
    return o;
}

// The optional "params" object (files written before V2.35 support have none).
QString paramsFromJson(const QJsonObject &params, SimParams *out)
{
    for (auto it = params.begin(); it != params.end(); ++it) {
        const auto id = protocol::ParamTable::fromName(it.key());
        const QByteArray bytes = QByteArray::fromHex(it.value().toString().toLatin1());
        if (!id || !it.value().isString() || bytes.size() != 6)
            return QStringLiteral("\"params.%1\" is not a parameter with six hex bytes")
                .arg(it.key());
        protocol::ParameterValue v;
        v.paramId = static_cast<quint8>(*id);
        for (int i = 0; i < 6; ++i)
            v.bytes[i] = static_cast<quint8>(bytes[i]);
        out->write(v);
    }
    return {};
}

// Parses a ROM object; returns an empty string on success, else what is wrong.
QString fromJson(const QJsonObject &o, int id, protocol::Series *series, SimRom *rom)
{
    if (o.value(QStringLiteral("format")).toString() != QLatin1String(kFormatName))
        return QStringLiteral("it is not a simulator ROM file (\"format\" is not \"%1\")")
            .arg(QLatin1String(kFormatName));
    qint64 v = 0;
    if (!readInt(o, "version", kFormatVersion, kFormatVersion, &v))
        return QStringLiteral("unsupported \"version\" (expected %1)").arg(kFormatVersion);
    if (!readInt(o, "id", id, id, &v))
        return QStringLiteral("\"id\" is not %1").arg(id);
    const auto s = protocol::seriesFromName(o.value(QStringLiteral("series")).toString());
    if (!s)
        return QStringLiteral("\"series\" is not one of MS, MF, MG, MH");
    *series = *s;
    const QJsonObject pid = o.value(QStringLiteral("pid")).toObject();
    for (int i = 0; i < 6; ++i) {
        if (!readInt(pid, kPidKeys[i], 0, 255, &v))
            return QStringLiteral("\"pid.%1\" must be an integer 0..255")
                .arg(QLatin1String(kPidKeys[i]));
        *pidField(rom->pid, i) = static_cast<quint8>(v);
    }
    if (!readInt(o, "accel_dps2", std::numeric_limits<qint32>::min(),
                 std::numeric_limits<qint32>::max(), &v))
        return QStringLiteral("\"accel_dps2\" must be a 32-bit integer");
    rom->accelDps2 = static_cast<qint32>(v);
    if (!readInt(o, "encoder_zero", 0, 65535, &v))
        return QStringLiteral("\"encoder_zero\" must be an integer 0..65535");
    rom->encoderZero = static_cast<quint16>(v);
    return paramsFromJson(o.value(QStringLiteral("params")).toObject(), &rom->params);
}
} // namespace

SimRomStore::SimRomStore(const QString &directory) : m_dir(directory)
{
    if (persistent())
        loadAll();
}

QString SimRomStore::filePath(int id) const
{
    return QDir(m_dir).filePath(QStringLiteral("rom-id%1.json").arg(id, 2, 10, QLatin1Char('0')));
}

void SimRomStore::addError(const QString &message)
{
    qCWarning(lcSim).noquote() << message;
    m_errors.append(message);
}

void SimRomStore::loadAll()
{
    QDir dir(m_dir);
    if (!dir.exists() && !QDir().mkpath(m_dir)) {
        addError(QStringLiteral("Cannot create the ROM directory %1: drives start with "
                                "defaults and ROM writes will not be kept.")
                     .arg(QDir::toNativeSeparators(m_dir)));
        return;
    }
    static const QRegularExpression nameRe(QStringLiteral("^rom-id(\\d\\d)\\.json$"));
    // Every entry with a ROM file name, so that one that cannot be read is reported too.
    const QStringList files =
        dir.entryList({QStringLiteral("rom-id*.json")},
                      QDir::AllEntries | QDir::System | QDir::Hidden | QDir::NoDotAndDotDot);
    for (const QString &name : files) {
        const auto m = nameRe.match(name);
        const int id = m.hasMatch() ? m.captured(1).toInt() : 0;
        if (id >= 1 && id <= 32)
            loadFile(dir.filePath(name), id);
    }
}

void SimRomStore::loadFile(const QString &path, int id)
{
    const QString shown = QDir::toNativeSeparators(path);
    const system::BoundedRead file = system::BoundedFile::read(path, kMaxFileSize);
    if (!file.ok()) { // unreadable, not a regular file, or too large to be a ROM file
        addError(QStringLiteral("Cannot read ROM file %1 (%2): drive %3 starts with defaults.")
                     .arg(shown, file.error->reason())
                     .arg(id));
        return;
    }
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(file.bytes, &parseError);
    QString problem;
    if (parseError.error != QJsonParseError::NoError)
        problem = QStringLiteral("invalid JSON at offset %1: %2")
                      .arg(parseError.offset)
                      .arg(parseError.errorString());
    else if (!doc.isObject())
        problem = QStringLiteral("the top level is not a JSON object");
    Entry entry{protocol::Series::MF, SimRom{}};
    if (problem.isEmpty())
        problem = fromJson(doc.object(), id, &entry.series, &entry.rom);
    if (!problem.isEmpty()) {
        addError(QStringLiteral("ROM file %1 is corrupt (%2): drive %3 starts with defaults.")
                     .arg(shown, problem)
                     .arg(id));
        return;
    }
    m_entries.insert(id, entry);
}

std::optional<SimRom> SimRomStore::rom(int id, protocol::Series series)
{
    const auto it = m_entries.constFind(id);
    if (it == m_entries.constEnd())
        return std::nullopt;
    if (it->series != series) {
        addError(QStringLiteral("ROM for ID %1 belongs to an %2 drive, but ID %1 is an %3 "
                                "now: it starts with defaults.")
                     .arg(id)
                     .arg(protocol::seriesName(it->series), protocol::seriesName(series)));
        return std::nullopt;
    }
    return it->rom;
}

bool SimRomStore::save(int id, protocol::Series series, const SimRom &rom)
{
    m_entries.insert(id, Entry{series, rom});
    if (!persistent())
        return true;
    const QByteArray bytes = QJsonDocument(toJson(id, series, rom)).toJson(QJsonDocument::Indented);
    const QString why = system::AtomicFile::writeAll(filePath(id), bytes);
    if (!why.isEmpty()) { // nothing replaced the earlier file
        addError(QStringLiteral("Cannot write ROM file %1 (%2): the change lasts only until "
                                "the simulator exits.")
                     .arg(QDir::toNativeSeparators(filePath(id)), why));
        return false;
    }
    return true;
}

} // namespace lk::sim
