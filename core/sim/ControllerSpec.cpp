#include "ControllerSpec.h"

#include "protocol/Checksum.h"
#include "protocol/RequestBuilder.h"

#include <QtCore/QSet>
#include <QtCore/QStringList>

#include <cmath>

namespace lk::sim {

namespace {

using protocol::Command;
using protocol::CommandTable;

constexpr double kMaxRateHz = 100000;
constexpr double kMaxTimeoutMs = 1000;
const QString kSineSyntax =
    QStringLiteral("write sine:AMPLITUDEdps:FREQUENCYHz, e.g. sine:300dps:0.5Hz");

/// "300dps" with unit "dps" -> 300; nullopt unless the text is a finite number then the unit.
std::optional<double> quantity(const QString &part, const QString &unit)
{
    if (!part.endsWith(unit, Qt::CaseInsensitive) || part.size() == unit.size())
        return std::nullopt;
    bool ok = false;
    const double v = part.left(part.size() - unit.size()).toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return std::nullopt;
    return v;
}

/// Helper that carries the key being parsed into every refusal.
class KeyParser {
public:
    KeyParser(QString key, QString value, QString *error)
        : m_key(std::move(key)), m_value(std::move(value)), m_error(error)
    {
    }
    bool fail(const QString &why) const
    {
        if (m_error)
            *m_error = QStringLiteral("--controller: %1=%2: %3").arg(m_key, m_value, why);
        return false;
    }

    bool rate(ControllerSpec &spec) const
    {
        if (m_value == QLatin1String("max")) {
            spec.rateHz = 0;
            return true;
        }
        bool ok = false;
        const double hz = m_value.toDouble(&ok);
        if (!ok || !(hz > 0 && hz <= kMaxRateHz))
            return fail(QStringLiteral("the rate must be requests per second, more than 0 and "
                                       "at most %1, or max")
                            .arg(kMaxRateHz));
        spec.rateHz = hz;
        return true;
    }

    bool ids(ControllerSpec &spec) const
    {
        QSet<int> seen;
        for (const QString &part : m_value.split(QLatin1Char(':'))) {
            const QStringList ends = part.split(QLatin1Char('-'));
            bool okFirst = false;
            bool okLast = ends.size() <= 2;
            const int first = ends.first().toInt(&okFirst);
            const int last = ends.size() == 2 ? ends.last().toInt(&okLast) : first;
            if (!okFirst || !okLast || first < protocol::kMinId || last > protocol::kMaxId ||
                last < first)
                return fail(
                    QStringLiteral("'%1' is not an ID 1..32 or a range such as 1-4").arg(part));
            for (int id = first; id <= last; ++id) {
                if (seen.contains(id))
                    return fail(QStringLiteral("ID %1 is given twice").arg(id));
                seen.insert(id);
                spec.ids.append(id);
            }
        }
        return true;
    }

    bool poll(ControllerSpec &spec) const
    {
        spec.poll.clear();
        if (m_value == QLatin1String("none"))
            return true;
        for (const QString &part : m_value.split(QLatin1Char(':'))) {
            std::optional<Command> c = CommandTable::fromName(part.toLower());
            if (!c) {
                QString hex = part.toLower();
                if (hex.startsWith(QLatin1String("0x")))
                    hex = hex.mid(2);
                bool ok = false;
                const uint code = hex.toUInt(&ok, 16);
                if (ok && hex.size() <= 2 && CommandTable::find(static_cast<quint8>(code)))
                    c = static_cast<Command>(code);
            }
            if (!c || !ControllerSpec::isPollable(*c))
                return fail(QStringLiteral("'%1' is not a read without data (read_state2 or 9c, "
                                           "read_state1, read_state3, read_multi_turn, "
                                           "read_single_turn, read_encoder, read_pid, "
                                           "read_accel, read_model), nor none")
                                .arg(part));
            spec.poll.append(*c);
        }
        return true;
    }

    bool speed(ControllerSpec &spec) const
    {
        const QStringList parts = m_value.split(QLatin1Char(':'));
        if (parts.size() != 3 || parts.first() != QLatin1String("sine"))
            return fail(kSineSyntax);
        const std::optional<double> a = quantity(parts[1], QStringLiteral("dps"));
        const std::optional<double> f = quantity(parts[2], QStringLiteral("Hz"));
        if (!a || !f)
            return fail(kSineSyntax);
        if (!(*a > 0) || !protocol::build::speed(1, *a).ok())
            return fail(QStringLiteral("the amplitude must be more than 0 and fit the speed "
                                       "command"));
        if (!(*f > 0 && *f <= 1000))
            return fail(QStringLiteral("the frequency must be more than 0 and at most 1000 Hz"));
        spec.speed = ControllerSpec::Sine{*a, *f};
        return true;
    }

    bool move(ControllerSpec &spec) const
    {
        QStringList parts = m_value.split(QLatin1Char(':'));
        const std::optional<double> period =
            parts.size() >= 2 ? quantity(parts[1], QStringLiteral("s")) : std::nullopt;
        if (parts.size() < 2 || parts.size() > 4 || parts.first() != QLatin1String("every") ||
            !period)
            return fail(QStringLiteral("write every:PERIODs[:STEPdeg][:MAXdps], e.g. "
                                       "every:5s:90deg:360dps"));
        ControllerSpec::Move m;
        m.periodS = *period;
        bool haveStep = false;
        bool haveSpeed = false;
        for (qsizetype i = 2; i < parts.size(); ++i) {
            if (const std::optional<double> v = quantity(parts[i], QStringLiteral("deg"));
                v && !haveStep) {
                m.stepDeg = *v;
                haveStep = true;
            } else if (const std::optional<double> s = quantity(parts[i], QStringLiteral("dps"));
                       s && !haveSpeed) {
                m.maxSpeedDps = *s;
                haveSpeed = true;
            } else {
                return fail(QStringLiteral("'%1' is neither a step in deg nor a speed in dps "
                                           "(each at most once)")
                                .arg(parts[i]));
            }
        }
        if (!(m.periodS >= 0.01 && m.periodS <= 86400))
            return fail(QStringLiteral("the period must be 0.01..86400 s"));
        if (!(m.stepDeg > 0) ||
            !protocol::build::incrementPosition(1, m.stepDeg, m.maxSpeedDps).ok())
            return fail(QStringLiteral("the step must be more than 0 deg and, with the speed, "
                                       "fit increment_position_limited"));
        if (!(m.maxSpeedDps > 0))
            return fail(QStringLiteral("the speed must be more than 0 dps"));
        spec.move = m;
        return true;
    }

    bool timeout(ControllerSpec &spec) const
    {
        const std::optional<double> ms = quantity(m_value, QStringLiteral("ms"));
        if (!ms || !(*ms > 0 && *ms <= kMaxTimeoutMs))
            return fail(QStringLiteral("write the time in ms, more than 0 and at most %1, "
                                       "e.g. 5ms")
                            .arg(kMaxTimeoutMs));
        spec.timeoutS = *ms * 1e-3;
        return true;
    }

private:
    QString m_key;
    QString m_value;
    QString *m_error;
};

QString idsText(const QList<int> &ids)
{
    QStringList parts;
    for (qsizetype i = 0; i < ids.size();) {
        qsizetype j = i;
        while (j + 1 < ids.size() && ids[j + 1] == ids[j] + 1)
            ++j;
        parts.append(j > i ? QStringLiteral("%1-%2").arg(ids[i]).arg(ids[j])
                           : QString::number(ids[i]));
        i = j + 1;
    }
    return parts.join(QLatin1Char(':'));
}

} // namespace

bool ControllerSpec::isPollable(Command command)
{
    const protocol::CommandInfo &info = CommandTable::info(command);
    return info.requestLength == 0 && !info.movesMotor && !info.writesFlash &&
           QLatin1String(info.name).startsWith(QLatin1String("read_"));
}

std::optional<ControllerSpec> ControllerSpec::parse(const QString &text, QString *error)
{
    using Member = bool (KeyParser::*)(ControllerSpec &) const;
    static const QList<QPair<QString, Member>> kKeys{
        {QStringLiteral("rate"), &KeyParser::rate},
        {QStringLiteral("ids"), &KeyParser::ids},
        {QStringLiteral("poll"), &KeyParser::poll},
        {QStringLiteral("speed"), &KeyParser::speed},
        {QStringLiteral("move"), &KeyParser::move},
        {QStringLiteral("timeout"), &KeyParser::timeout},
    };
    ControllerSpec spec;
    QSet<QString> seen;
    for (const QString &item : text.split(QLatin1Char(','))) {
        const qsizetype eq = item.indexOf(QLatin1Char('='));
        const QString key = item.left(eq).trimmed();
        const QString value = eq < 0 ? QString() : item.mid(eq + 1).trimmed();
        Member member = nullptr;
        for (const auto &k : kKeys) {
            if (k.first == key)
                member = k.second;
        }
        const KeyParser parser(key, value, error);
        if (!member) {
            if (error)
                *error = QStringLiteral("--controller: unknown key '%1' (keys: rate, ids, poll, "
                                        "speed, move, timeout)")
                             .arg(key);
            return std::nullopt;
        }
        if (eq < 0 || value.isEmpty()) {
            parser.fail(QStringLiteral("the key needs a value"));
            return std::nullopt;
        }
        if (seen.contains(key)) {
            parser.fail(QStringLiteral("the key is given twice"));
            return std::nullopt;
        }
        seen.insert(key);
        if (!(parser.*member)(spec))
            return std::nullopt;
    }
    if (spec.poll.isEmpty() && !spec.speed && !spec.move) {
        if (error)
            *error = QStringLiteral("--controller: poll=none: with no speed= or move= the "
                                    "controller would send nothing");
        return std::nullopt;
    }
    return spec;
}

QString ControllerSpec::toString() const
{
    QStringList items;
    items.append(QStringLiteral("rate=%1").arg(rateHz > 0 ? QString::number(rateHz)
                                                          : QStringLiteral("max")));
    if (!ids.isEmpty())
        items.append(QStringLiteral("ids=%1").arg(idsText(ids)));
    QStringList codes;
    for (Command c : poll)
        codes.append(QString::number(static_cast<quint8>(c), 16));
    items.append(QStringLiteral("poll=%1").arg(codes.isEmpty() ? QStringLiteral("none")
                                                               : codes.join(QLatin1Char(':'))));
    if (speed)
        items.append(QStringLiteral("speed=sine:%1dps:%2Hz")
                         .arg(speed->amplitudeDps)
                         .arg(speed->frequencyHz));
    if (move)
        items.append(QStringLiteral("move=every:%1s:%2deg:%3dps")
                         .arg(move->periodS)
                         .arg(move->stepDeg)
                         .arg(move->maxSpeedDps));
    items.append(QStringLiteral("timeout=%1ms").arg(timeoutS * 1e3));
    return items.join(QLatin1Char(','));
}

} // namespace lk::sim
