#pragma once

#include <tuning/GainSearchRunner.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

namespace lk::ui {

/// A gain search's end in the user's words, from its typed outcome (tuning::TuningOutcome):
/// why it ended, what the drive was left doing, whether the gains read are back in RAM.
class GainSearchViewOutcome {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::GainSearchViewOutcome)
public:
    /// The whole status line of `result` (the candidates tried, the suggestion, the drive).
    static QString text(const tuning::GainSearchResult &result);
    /// Why it ended ("Stopped.", "Refused: ...").
    static QString endText(const tuning::GainSearchResult &result);
    /// What drive `id` was left doing.
    static QString driveText(const tuning::TuningOutcome &outcome, int id);
    /// Whether the gains read are back (empty when nothing was ever written).
    static QString gainsText(const tuning::TuningOutcome &outcome);
};

} // namespace lk::ui
