#include "TuningFile.h"

#include "ParameterFileText.h"

#include <QtCore/QLocale>

namespace lk::ui {

TuningFileResult TuningFile::save(const QString &path, const ParamSetSpec &spec,
                                  const HeldValues &held, int id, const bus::KnownMotor &motor,
                                  std::optional<protocol::Series> series)
{
    TuningFileResult result;
    record::ParameterSet set;
    if (id <= 0 || !spec.toFile(held, set)) {
        result.error = tr("Nothing to save: read the drive's parameters first.");
        result.status = result.error;
        return result;
    }
    set.driveId = id;
    if (const auto &m = motor.model) {
        set.driverName = m->driverName;
        set.motorName = m->motorName;
        set.hardwareVersion = m->hardwareVersion();
        set.firmwareVersion = m->firmwareVersion();
    }
    set.series = series;
    set.savedAt = QDateTime::currentDateTimeUtc();
    result.error = set.save(path);
    result.status = result.error.isEmpty()
                        ? tr("Saved the parameters of drive %1 to %2.").arg(id).arg(path)
                        : tr("Could not save: %1").arg(result.error);
    return result;
}

TuningFileResult TuningFile::load(const QString &path, const ParamSetSpec &spec,
                                  const ParamValues &current, const bus::KnownMotor &motor)
{
    TuningFileResult result;
    record::ParameterFileError fault;
    const std::optional<record::ParameterSet> set = record::ParameterSet::load(path, &fault);
    if (!set) {
        result.error = ParameterFileText::describe(fault);
    } else if (set->generation != spec.generation() ||
               !(result.values = spec.fromFile(*set, current))) {
        result.error =
            tr("the file holds the gains of a protocol %1 drive, this drive speaks %2: the gains "
               "of the two generations differ in number and range")
                .arg(protocol::generationName(set->generation),
                     protocol::generationName(spec.generation()));
    }
    if (!result.error.isEmpty()) {
        result.values.reset();
        result.status = tr("Could not load %1: %2. Nothing was changed.").arg(path, result.error);
        return result;
    }
    result.status = (spec.ramOnly() ? tr("Loaded the parameters of drive %1 (%2, firmware %3, "
                                         "saved %4) into the pending edit: nothing is written "
                                         "until you write to RAM (this drive has no ROM write).")
                                    : tr("Loaded the parameters of drive %1 (%2, firmware %3, "
                                         "saved %4) into the pending edit: nothing is written "
                                         "until you write to RAM or ROM."))
                        .arg(set->driveId)
                        .arg(set->motorName.isEmpty() ? tr("unknown motor") : set->motorName)
                        .arg(set->firmwareVersion)
                        .arg(QLocale().toString(set->savedAt.toLocalTime(), QLocale::ShortFormat));
    const QString here = motor.model ? motor.model->motorName : QString();
    if (!set->motorName.isEmpty() && !here.isEmpty() && set->motorName != here)
        result.status +=
            QLatin1Char(' ') +
            tr("Careful: the file comes from a %1, this drive is a %2.").arg(set->motorName, here);
    return result;
}

} // namespace lk::ui
