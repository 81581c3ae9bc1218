#pragma once

#include "FrequencyRun.h"

#include <record/ParameterSet.h>

#include <QtCore/QJsonObject>
#include <QtCore/QString>

#include <optional>

namespace lk::tuning {

/// Saves and loads one frequency run (#25), so that today's response can be overlaid on last
/// week's. `NAME.lkfreq.json`:
/// {"format":"lkstudio-frequency-run","version":1,"number","label","ran_at","drive_id","series",
/// "model","loop":"speed"|"position","from_hz","to_hz","points_planned","amplitude",
/// "operating_point","gains":{...}|null,"sample_rate_hz","points":[{"hz","magnitude_db",
/// "phase_deg","quality","samples","input_amplitude","output_amplitude"}],"dropped":[{"hz",
/// "reason"}]}. Every key is checked on load (record::ParameterFileCheck): a key missing,
/// unknown, of the wrong type or out of range refuses the file with the key named (points[2].hz).
/// Read through BoundedFile, at most kMaxFileBytes; written atomically.
class FrequencyRunFile {
public:
    static constexpr char kFormatName[] = "lkstudio-frequency-run";
    static constexpr int kFormatVersion = 1;
    static constexpr char kSuffix[] = ".lkfreq.json";
    /// 60 points and their drops are a few kilobytes; a larger file is refused unread.
    static constexpr qint64 kMaxFileBytes = 1 << 20;

    static QJsonObject toJson(const FrequencyRun &run);
    /// nullopt with `error` naming the key (its path from the top) on any bad value.
    static std::optional<FrequencyRun> fromJson(const QJsonObject &root,
                                                record::ParameterFileError *error = nullptr);
    /// An error text, empty on success.
    static QString save(const QString &path, const FrequencyRun &run);
    static std::optional<FrequencyRun> load(const QString &path,
                                            record::ParameterFileError *error = nullptr);
    /// "loop" and the dropped frequencies' "reason" words.
    static QString loopWord(SweepLoop loop);
    static const char *droppedWord(DroppedReason reason);
};

} // namespace lk::tuning
