#pragma once

#include <QtCore/QString>

namespace lk::ui {

/// Whether a clear-angle command (0x95) took effect, judged from the multi-turn angle read
/// before and after it (ERRATA: some firmware acknowledges 0x95 and does nothing).
struct AngleCheck {
    enum class Outcome {
        Cleared,        ///< the angle now reads (about) zero
        AlreadyZero,    ///< it read zero before too: nothing to tell
        Unchanged,      ///< acknowledged, but the angle stayed where it was
        ChangedNotZero, ///< it moved but is not zero (the motor was turning?)
    };
    static constexpr double kToleranceDeg = 1.0;

    Outcome outcome = Outcome::Unchanged;
    double beforeDeg = 0;
    double afterDeg = 0;

    static AngleCheck classify(double beforeDeg, double afterDeg,
                               double toleranceDeg = kToleranceDeg);
};

} // namespace lk::ui
