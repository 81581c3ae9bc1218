#pragma once

#include "ParamSetSpec.h"

#include <bus/KnownMotor.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

#include <optional>

namespace lk::ui {

/// What saving or loading a parameter file came to: the status line to show, whether it is an
/// error, and (load) the pending edit the file gives.
struct TuningFileResult {
    QString error;  ///< empty on success
    QString status; ///< the whole sentence for the status line
    std::optional<ParamValues> values;
};

/// A drive's tuning set to and from parameter files (record::ParameterSet): the file records
/// the protocol generation, and a file of the other generation is refused with the reason.
class TuningFile {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::TuningFile)
public:
    /// Saves what drive `id` holds, with its model, firmware and the time.
    static TuningFileResult save(const QString &path, const ParamSetSpec &spec,
                                 const HeldValues &held, int id, const bus::KnownMotor &motor,
                                 std::optional<protocol::Series> series);
    /// Reads a file into a pending edit (values the file lacks come from `current`).
    static TuningFileResult load(const QString &path, const ParamSetSpec &spec,
                                 const ParamValues &current, const bus::KnownMotor &motor);
};

} // namespace lk::ui
