#pragma once

#include "StepRunFile.h"
#include "StepTrace.h"

#include <QtCore/QByteArray>
#include <QtCore/QIODevice>

namespace lk::tuning {

/// The CSV of a kept run's trace: "time_s,value,effort", times counted from `origin`, C
/// locale, an effort the sample did not carry as an empty cell (never 0).
class StepTraceCsv {
public:
    static QByteArray header(); ///< "time_s,value,effort\n"
    /// `time` as the files hold it: counted from `origin`, rounded as the CSV writes it. The
    /// JSON's edge times go through it too, so an edge that had a sample's time keeps it.
    static double fileTime(double time, double origin);
    /// One line per sample, times counted from `origin` (no header).
    static QByteArray rows(const StepTrace &trace, double origin);
    /// Reads the samples of `device` into `trace` (time, value, effort; edges untouched).
    /// Refuses a wrong header, a line without three cells, a cell that is not a finite number
    /// (effort may be empty) and a time before the one before it (equal times pass: two
    /// samples closer than the file's microsecond may round to one), with `error` naming the
    /// line and column (its path is left to the caller).
    static bool read(QIODevice &device, StepTrace &trace, StepRunFileError *error);
};

} // namespace lk::tuning
