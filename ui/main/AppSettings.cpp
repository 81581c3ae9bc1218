#include "AppSettings.h"

#include "SettingsFile.h"

#include <bus/BusTiming.h>
#include <drive/DriveSettingsStore.h>

#include <QtCore/QRegularExpression>
#include <QtCore/QSettings>
#include <QtCore/QStringList>
#include <QtCore/QUrl>

namespace lk::ui {

namespace {

// Every key of the file, once. Groups mirror the panels that own the values.
namespace key {
const char kVersion[] = "settingsVersion";
const char kConnectionKind[] = "connection/kind";
const char kConnectionPort[] = "connection/port";
const char kConnectionBaud[] = "connection/baud";
const char kAutoReconnect[] = "connection/autoReconnect";
const char kListenOnly[] = "connection/listenOnly";
const char kCanPlugin[] = "connection/canPlugin";
const char kCanInterface[] = "connection/canInterface";
const char kCanBitRate[] = "connection/canBitRate";
const char kChosenSeriesGroup[] = "chosenSeries";         // /<port, percent-encoded>/<id>
const char kChosenGenerationGroup[] = "chosenGeneration"; // the same; "can" or "can236"
const char kScanFirstId[] = "scan/firstId";
const char kScanLastId[] = "scan/lastId";
const char kScanSweepBauds[] = "scan/sweepBauds";
const char kPollRateHz[] = "poll/rateHz";
const char kBlackBoxMinutes[] = "recording/blackBoxMinutes";
const char kLanguage[] = "ui/language";
const char kCurrentView[] = "window/currentView";
const char kWindowGeometry[] = "window/geometry";
const char kWindowState[] = "window/state";
const char kLastFolderGroup[] = "lastFolder/"; // + a FileDialogs purpose key
} // namespace key

const char kKindSerial[] = "serial";
const char kKindSimulator[] = "simulator";
const char kKindCan[] = "can";
const char kKindSimulatorCan[] = "simulator-can"; // the built-in simulator with CAN drives
constexpr int kMinId = 1;
constexpr int kMaxId = 32;
constexpr double kMaxPollRateHz = 10000;

bool validId(const QVariant &v)
{
    bool ok = false;
    const int id = v.toInt(&ok);
    return ok && id >= kMinId && id <= kMaxId;
}

bool validBaud(const QVariant &v)
{
    bool ok = false;
    const int baud = v.toInt(&ok);
    return ok && bus::BusTiming::isStandardBaud(baud);
}

bool validKind(const QVariant &v)
{
    const QString s = v.toString();
    return s == QLatin1String(kKindSerial) || s == QLatin1String(kKindSimulator) ||
           s == QLatin1String(kKindCan) || s == QLatin1String(kKindSimulatorCan);
}

bool validBitRate(const QVariant &v)
{
    bool ok = false;
    const int rate = v.toInt(&ok);
    return ok && ConnectionChoice::isCanBitRate(rate);
}

// A Qt SerialBus plugin key ("socketcan", "virtualcan"): lower-case letters and digits.
bool validCanPlugin(const QVariant &v)
{
    static const QRegularExpression re(QStringLiteral("^[a-z][a-z0-9]{0,31}$"));
    return re.match(v.toString()).hasMatch();
}

// An interface name: "can0", "slcan0", or virtualcan's "tcp://127.0.0.1:35468/can0"; no
// spaces, not empty, not absurdly long.
bool validCanInterface(const QVariant &v)
{
    static const QRegularExpression re(QStringLiteral("^[A-Za-z0-9_.:/@-]{1,128}$"));
    return re.match(v.toString()).hasMatch();
}

bool validRate(const QVariant &v)
{
    bool ok = false;
    const double hz = v.toDouble(&ok);
    return ok && hz >= 0 && hz <= kMaxPollRateHz;
}

// A locale name such as "zh_CN"; what is not shipped falls back in LanguageLoader.
bool validLanguage(const QString &s)
{
    static const QRegularExpression re(QStringLiteral("^[a-z]{2,3}(_[A-Z]{2})?$"));
    return s.isEmpty() || re.match(s).hasMatch();
}

bool validBool(const QVariant &v)
{
    const QString s = v.toString().toLower();
    return s == QLatin1String("true") || s == QLatin1String("false") || s == QLatin1String("1") ||
           s == QLatin1String("0");
}

bool validLanguageValue(const QVariant &v)
{
    return validLanguage(v.toString());
}

bool validSeries(const QVariant &v)
{
    return protocol::seriesFromName(v.toString()).has_value();
}

// "chosenSeries/%2Fdev%2FttyUSB0/3": the port's slashes must not open settings groups.
QString chosenKey(const char *group, const QString &port, int id)
{
    return QStringLiteral("%1/%2/%3")
        .arg(QLatin1String(group), QString::fromLatin1(QUrl::toPercentEncoding(port)))
        .arg(id);
}

QString chosenSeriesKey(const QString &port, int id)
{
    return chosenKey(key::kChosenSeriesGroup, port, id);
}

/// The CAN generations by the words of lkctl --drives: "can" (old), "can236" (V2.36).
QString canGenerationWord(protocol::Generation g)
{
    return g == protocol::Generation::V2_35 ? QStringLiteral("can236") : QStringLiteral("can");
}

std::optional<protocol::Generation> canGenerationFromWord(const QString &word)
{
    if (word == QLatin1String("can"))
        return protocol::Generation::V2_3;
    if (word == QLatin1String("can236"))
        return protocol::Generation::V2_35;
    return std::nullopt;
}

bool validBlackBoxMinutes(const QVariant &v)
{
    bool ok = false;
    const int minutes = v.toInt(&ok);
    return ok && minutes >= AppSettings::kMinBlackBoxMinutes &&
           minutes <= AppSettings::kMaxBlackBoxMinutes;
}

bool validVersion(const QVariant &v)
{
    bool ok = false;
    return v.toInt(&ok) >= 0 && ok;
}

// Every checked key with what it must be (for the damage report).
struct CheckedKey {
    const char *key;
    bool (*valid)(const QVariant &);
    const char *allowed;
};
const CheckedKey kCheckedKeys[] = {
    {key::kVersion, validVersion, "a whole number"},
    {key::kConnectionKind, validKind, "serial, can, simulator or simulator-can"},
    {key::kCanPlugin, validCanPlugin, "a Qt CAN plugin such as socketcan"},
    {key::kCanInterface, validCanInterface, "an interface name such as can0"},
    {key::kCanBitRate, validBitRate, "1000000, 500000, 250000, 125000 or 100000"},
    {key::kConnectionBaud, validBaud, "one of the nine LK bauds"},
    {key::kAutoReconnect, validBool, "true or false"},
    {key::kListenOnly, validBool, "true or false"},
    {key::kScanFirstId, validId, "1..32"},
    {key::kScanLastId, validId, "1..32"},
    {key::kScanSweepBauds, validBool, "true or false"},
    {key::kPollRateHz, validRate, "0..10000"},
    {key::kBlackBoxMinutes, validBlackBoxMinutes, "1..60 (minutes)"},
    {key::kLanguage, validLanguageValue, "a language such as zh_CN"},
};

void removeIf(QSettings &s, const char *k, bool (*valid)(const QVariant &))
{
    if (s.contains(QLatin1String(k)) && !valid(s.value(QLatin1String(k))))
        s.remove(QLatin1String(k));
}

// Step 0 -> 1: files without a version key come from development builds that wrote the
// same key names without checking them; keep what is valid, drop the rest.
void migrateFrom0(QSettings &s)
{
    removeIf(s, key::kConnectionKind, validKind);
    removeIf(s, key::kConnectionBaud, validBaud);
    removeIf(s, key::kAutoReconnect, validBool);
    removeIf(s, key::kScanFirstId, validId);
    removeIf(s, key::kScanLastId, validId);
    removeIf(s, key::kScanSweepBauds, validBool);
    removeIf(s, key::kPollRateHz, validRate);
}

} // namespace

AppSettings::AppSettings(SettingsFile &file) : m_file(file), m_settings(file.settings())
{
    readFile();
}

AppSettings::AppSettings(const QString &iniFile)
    : m_ownFile(std::make_unique<SettingsFile>(iniFile)), m_file(*m_ownFile),
      m_settings(m_file.settings())
{
    readFile();
}

void AppSettings::readFile()
{
    if (const std::optional<system::FileReadError> &problem = m_file.problem()) {
        // Not read at all: the settings start empty (defaults) in memory.
        m_damage = {QStringLiteral("%1: %2").arg(m_file.fileName(), problem->reason())};
        return;
    }
    // Before migrating: migration drops bad values, and the user must hear about them.
    m_damage = findDamage(m_settings);
    m_loadedVersion = migrate(m_settings);
}

QStringList AppSettings::findDamage(QSettings &settings)
{
    if (settings.status() == QSettings::FormatError)
        return {QStringLiteral("%1: not a readable settings file").arg(settings.fileName())};
    QStringList damage;
    for (const CheckedKey &k : kCheckedKeys) {
        if (settings.contains(QLatin1String(k.key)) &&
            !k.valid(settings.value(QLatin1String(k.key))))
            damage << QStringLiteral("%1: must be %2 (found \"%3\")")
                          .arg(QLatin1String(k.key), QLatin1String(k.allowed),
                               settings.value(QLatin1String(k.key)).toString());
    }
    for (const QString &k : settings.allKeys()) {
        if (k.startsWith(QLatin1String(key::kChosenSeriesGroup) + QLatin1Char('/')) &&
            !validSeries(settings.value(k)))
            damage << QStringLiteral("%1: must be MS, MF, MG or MH (found \"%2\")")
                          .arg(k, settings.value(k).toString());
        if (k.startsWith(QLatin1String(key::kChosenGenerationGroup) + QLatin1Char('/')) &&
            !canGenerationFromWord(settings.value(k).toString()))
            damage << QStringLiteral("%1: must be can or can236 (found \"%2\")")
                          .arg(k, settings.value(k).toString());
    }
    return damage + IniDriveStore::damagedEntries(settings);
}

QString AppSettings::damageReport() const
{
    if (const std::optional<system::FileReadError> &problem = m_file.problem())
        return tr("Your settings file %1 was not read (%2): lkstudio runs with default "
                  "settings, and what you change now is not saved.")
            .arg(fileName(), problem->reason());
    QStringList parts;
    if (isFromNewerRelease())
        parts << tr("Your settings file %1 was written by a newer lkstudio (%2 is %3; this "
                    "release knows up to %4): only the values this release understands are "
                    "used, and the file is not converted.")
                     .arg(fileName(), QLatin1String(key::kVersion))
                     .arg(m_loadedVersion)
                     .arg(kVersion);
    if (!m_damage.isEmpty())
        parts << tr("Your settings file %1 is damaged; these values were not used: %2.")
                     .arg(fileName(), m_damage.join(QStringLiteral("; ")));
    return parts.join(QLatin1Char(' '));
}

AppSettings::~AppSettings()
{
    m_settings.sync();
}

QString AppSettings::fileName() const
{
    return m_file.fileName(); // the user's file, also when it was refused
}

int AppSettings::migrate(QSettings &settings)
{
    const int found = settings.value(QLatin1String(key::kVersion), 0).toInt();
    if (found > kVersion)
        return found; // a newer release wrote it: its layout is unknown here, leave it be
    if (found < 1)
        migrateFrom0(settings);
    // Future steps go here in order: if (found < 2) migrateFrom1(settings); ...
    settings.setValue(QLatin1String(key::kVersion), kVersion);
    return found;
}

ConnectionChoice AppSettings::connection() const
{
    const QSettings &s = m_settings;
    ConnectionChoice c;
    const QString kind = s.value(QLatin1String(key::kConnectionKind)).toString();
    c.kind = kind == QLatin1String(kKindSerial) ? ConnectionChoice::Kind::Serial
             : kind == QLatin1String(kKindCan)  ? ConnectionChoice::Kind::Can
                                                : ConnectionChoice::Kind::Simulator;
    c.simulatedCan = kind == QLatin1String(kKindSimulatorCan);
    c.port = s.value(QLatin1String(key::kConnectionPort)).toString();
    const QVariant baud = s.value(QLatin1String(key::kConnectionBaud));
    c.baud = validBaud(baud) ? baud.toInt() : bus::BusTiming::kDefaultBaud;
    // Damaged CAN values were named at start (damage()) and are not used: the defaults stand.
    const QVariant plugin = s.value(QLatin1String(key::kCanPlugin));
    if (validCanPlugin(plugin))
        c.canPlugin = plugin.toString();
    const QVariant iface = s.value(QLatin1String(key::kCanInterface));
    if (validCanInterface(iface))
        c.canInterface = iface.toString();
    const QVariant rate = s.value(QLatin1String(key::kCanBitRate));
    if (validBitRate(rate))
        c.bitRate = rate.toInt();
    c.autoReconnect = s.value(QLatin1String(key::kAutoReconnect), true).toBool();
    const QVariant listen = s.value(QLatin1String(key::kListenOnly), false);
    c.listenOnly = validBool(listen) && listen.toBool();
    return c;
}

void AppSettings::setConnection(const ConnectionChoice &choice)
{
    QSettings &s = m_settings;
    s.setValue(QLatin1String(key::kConnectionKind),
               QLatin1String(choice.isCan() ? kKindCan
                             : choice.isSimulator()
                                 ? (choice.simulatedCan ? kKindSimulatorCan : kKindSimulator)
                                 : kKindSerial));
    s.setValue(QLatin1String(key::kConnectionPort), choice.port);
    s.setValue(QLatin1String(key::kConnectionBaud), choice.baud);
    s.setValue(QLatin1String(key::kCanPlugin), choice.canPlugin);
    s.setValue(QLatin1String(key::kCanInterface), choice.canInterface);
    s.setValue(QLatin1String(key::kCanBitRate), choice.bitRate);
    s.setValue(QLatin1String(key::kAutoReconnect), choice.autoReconnect);
    s.setValue(QLatin1String(key::kListenOnly), choice.listenOnly);
}

std::optional<protocol::Series> AppSettings::chosenSeries(const QString &port, int id) const
{
    return protocol::seriesFromName(m_settings.value(chosenSeriesKey(port, id)).toString());
}

void AppSettings::setChosenSeries(const QString &port, int id, protocol::Series series)
{
    m_settings.setValue(chosenSeriesKey(port, id), protocol::seriesName(series));
}

std::optional<protocol::Generation> AppSettings::chosenGeneration(const QString &port, int id) const
{
    return canGenerationFromWord(
        m_settings.value(chosenKey(key::kChosenGenerationGroup, port, id)).toString());
}

void AppSettings::setChosenGeneration(const QString &port, int id, protocol::Generation generation)
{
    m_settings.setValue(chosenKey(key::kChosenGenerationGroup, port, id),
                        canGenerationWord(generation));
}

int AppSettings::scanFirstId() const
{
    const QVariant v = m_settings.value(QLatin1String(key::kScanFirstId));
    return validId(v) ? v.toInt() : kMinId;
}

int AppSettings::scanLastId() const
{
    const QVariant v = m_settings.value(QLatin1String(key::kScanLastId));
    const int last = validId(v) ? v.toInt() : kMaxId;
    return qMax(last, scanFirstId());
}

bool AppSettings::scanSweepBauds() const
{
    return m_settings.value(QLatin1String(key::kScanSweepBauds), false).toBool();
}

void AppSettings::setScanRange(int firstId, int lastId, bool sweepBauds)
{
    m_settings.setValue(QLatin1String(key::kScanFirstId), qBound(kMinId, firstId, kMaxId));
    m_settings.setValue(QLatin1String(key::kScanLastId), qBound(kMinId, lastId, kMaxId));
    m_settings.setValue(QLatin1String(key::kScanSweepBauds), sweepBauds);
}

double AppSettings::pollRateHz() const
{
    const QVariant v = m_settings.value(QLatin1String(key::kPollRateHz));
    return validRate(v) ? v.toDouble() : 0.0;
}

void AppSettings::setPollRateHz(double hz)
{
    m_settings.setValue(QLatin1String(key::kPollRateHz), qBound(0.0, hz, kMaxPollRateHz));
}

int AppSettings::blackBoxMinutes() const
{
    const QVariant v = m_settings.value(QLatin1String(key::kBlackBoxMinutes));
    return validBlackBoxMinutes(v) ? v.toInt() : kDefaultBlackBoxMinutes;
}

bool AppSettings::setBlackBoxMinutes(int minutes)
{
    if (!validBlackBoxMinutes(minutes))
        return false;
    m_settings.setValue(QLatin1String(key::kBlackBoxMinutes), minutes);
    return true;
}

QString AppSettings::language() const
{
    const QString language = m_settings.value(QLatin1String(key::kLanguage)).toString();
    return validLanguage(language) ? language : QString();
}

void AppSettings::setLanguage(const QString &language)
{
    if (validLanguage(language) && !language.isEmpty())
        m_settings.setValue(QLatin1String(key::kLanguage), language);
    else
        m_settings.remove(QLatin1String(key::kLanguage));
}

QString AppSettings::currentView() const
{
    return m_settings.value(QLatin1String(key::kCurrentView)).toString();
}

void AppSettings::setCurrentView(const QString &name)
{
    m_settings.setValue(QLatin1String(key::kCurrentView), name);
}

QString AppSettings::lastFolder(const QString &purpose) const
{
    return m_settings.value(QLatin1String(key::kLastFolderGroup) + purpose).toString();
}

void AppSettings::setLastFolder(const QString &purpose, const QString &folder)
{
    m_settings.setValue(QLatin1String(key::kLastFolderGroup) + purpose, folder);
}

QByteArray AppSettings::windowGeometry() const
{
    return m_settings.value(QLatin1String(key::kWindowGeometry)).toByteArray();
}

QByteArray AppSettings::windowState() const
{
    return m_settings.value(QLatin1String(key::kWindowState)).toByteArray();
}

void AppSettings::setWindow(const QByteArray &geometry, const QByteArray &state)
{
    m_settings.setValue(QLatin1String(key::kWindowGeometry), geometry);
    m_settings.setValue(QLatin1String(key::kWindowState), state);
}

void AppSettings::sync()
{
    m_settings.sync();
}

} // namespace lk::ui
