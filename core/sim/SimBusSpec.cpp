#include "SimBusSpec.h"

#include "protocol/Checksum.h"

#include <QtCore/QSet>
#include <QtCore/QStringList>

namespace lk::sim {

namespace {

const QLatin1String kFaultPrefix("fault=");

std::optional<SimDriveModel> modelFor(const QString &token)
{
    if (const auto series = protocol::seriesFromName(token))
        return SimDriveModel::forSeries(*series);
    return SimDriveModel::forMotorName(token);
}

} // namespace

bool SimBusSpec::addFaults(const QString &text, QString *error)
{
    auto fail = [error](const QString &message) {
        if (error)
            *error = message;
        return false;
    };
    for (const QString &raw : text.split(QLatin1Char(','))) {
        const QString item = raw.trimmed();
        const qsizetype colon = item.indexOf(QLatin1Char(':'));
        bool ok = false;
        const int id = colon < 0 ? 0 : item.left(colon).trimmed().toInt(&ok);
        if (!ok)
            return fail(QStringLiteral("'%1' is not ID:FAULT[@START[-END]] (e.g. "
                                       "1:over_temperature@5s)")
                            .arg(item));
        Entry *entry = nullptr;
        for (Entry &e : drives) {
            if (e.id == id)
                entry = &e;
        }
        if (!entry)
            return fail(QStringLiteral("'%1': there is no drive %2 on the bus").arg(item).arg(id));
        QString why;
        const auto fault = SimFault::parse(item.mid(colon + 1), entry->model.generation, &why);
        if (!fault)
            return fail(QStringLiteral("'%1': %2").arg(item, why));
        entry->model.faults.append(*fault);
    }
    return true;
}

std::optional<SimBusSpec> SimBusSpec::parse(const QString &text, QString *error)
{
    auto fail = [error](const QString &message) -> std::optional<SimBusSpec> {
        if (error)
            *error = message;
        return std::nullopt;
    };
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty())
        return fail(QStringLiteral("no drives given: expected ID:SERIES[,ID:SERIES...], "
                                   "e.g. 1:MF,2:MG"));
    SimBusSpec spec;
    QSet<int> seen;
    const QStringList items = trimmed.split(QLatin1Char(','));
    for (const QString &raw : items) {
        const QString item = raw.trimmed();
        if (item.isEmpty())
            return fail(QStringLiteral("empty entry in '%1': expected ID:SERIES between "
                                       "the commas")
                            .arg(trimmed));
        const qsizetype colon = item.indexOf(QLatin1Char(':'));
        if (colon < 0)
            return fail(QStringLiteral("'%1' is not ID:SERIES (e.g. 3:MF)").arg(item));
        const QString idText = item.left(colon).trimmed();
        const QString seriesText = item.mid(colon + 1).trimmed();
        bool ok = false;
        const int id = idText.toInt(&ok);
        if (!ok || id < protocol::kMinId || id > protocol::kMaxId)
            return fail(
                QStringLiteral("'%1': the ID must be a number 1..32, got '%2'").arg(item, idText));
        if (seen.contains(id))
            return fail(QStringLiteral("'%1': ID %2 is given twice").arg(item).arg(id));
        QStringList parts = seriesText.split(QLatin1Char('+'));
        QString modelText = parts.takeFirst().trimmed();
        QString firmware;
        if (const qsizetype at = modelText.indexOf(QLatin1Char('@')); at >= 0) {
            firmware = modelText.mid(at + 1).trimmed();
            modelText = modelText.left(at).trimmed();
        }
        auto model = modelFor(modelText);
        if (!model)
            return fail(QStringLiteral("'%1': unknown series '%2' (expected MS, MF, MG, MH "
                                       "or a motor name such as MG5010E-i10)")
                            .arg(item, seriesText));
        if (!firmware.isEmpty()) {
            // On CAN (lksim --can) "can" is the old generation, "can236" V2.36.
            const auto generation = protocol::generationFromWord(firmware);
            if (!generation)
                return fail(QStringLiteral("'%1': unknown firmware '%2' (2.3 or 2.35; on CAN "
                                           "can or can236)")
                                .arg(item, firmware));
            if (*generation == protocol::Generation::V2_35)
                model->useFirmware235();
        }
        for (const QString &part : parts) {
            const QString quirk = part.trimmed();
            if (quirk.startsWith(kFaultPrefix, Qt::CaseInsensitive)) {
                QString why;
                const auto fault =
                    SimFault::parse(quirk.mid(kFaultPrefix.size()), model->generation, &why);
                if (!fault)
                    return fail(QStringLiteral("'%1': %2").arg(item, why));
                model->faults.append(*fault);
                continue;
            }
            if (PlantOptions::isItem(quirk)) {
                QString why;
                if (!model->plant.parseItem(quirk, &why))
                    return fail(QStringLiteral("'%1': %2").arg(item, why));
                continue;
            }
            if (!model->quirks.enable(quirk))
                return fail(
                    QStringLiteral("'%1': unknown firmware quirk '%2' (known: %3)")
                        .arg(item, quirk, FirmwareQuirks::allNames().join(QStringLiteral(", "))));
        }
        seen.insert(id);
        spec.drives.append(Entry{id, *model});
    }
    return spec;
}

QString SimBusSpec::toString() const
{
    QStringList parts;
    for (const Entry &e : drives) {
        const bool standard =
            e.model.motorName == SimDriveModel::forSeries(e.model.series).motorName;
        QString name = standard ? protocol::seriesName(e.model.series) : e.model.motorName;
        if (e.model.generation == protocol::Generation::V2_35)
            name += QStringLiteral("@2.35");
        QStringList model{name};
        model << e.model.quirks.names();
        for (const SimFault &f : e.model.faults)
            model << kFaultPrefix + f.toString(e.model.generation);
        if (const QString plant = e.model.plant.toString(); !plant.isEmpty())
            model << plant;
        parts << QStringLiteral("%1:%2").arg(e.id).arg(model.join(QLatin1Char('+')));
    }
    return parts.join(QLatin1Char(','));
}

} // namespace lk::sim
