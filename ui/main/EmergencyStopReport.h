#pragma once

#include <panels/MessageBanner.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QStringList>
#include <QtCore/QVector>

namespace lk::ui {

/// The wording of one emergency stop's banner report, from what the bus said of it: who
/// acknowledged, who stayed silent, and which never got the halt on the wire; while the stop
/// is under way, what has come back so far; afterwards, which of the drives said in red to
/// be possibly moving have since read stopped. Pure, so each case is tested without a bus.
class EmergencyStopReport {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::EmergencyStopReport)
public:
    /// The drives the stop had in mind when it began.
    struct Context {
        QVector<int> watched;  ///< known or commanded IDs
        QStringList commanded; ///< "Drive 2 (speed 360 dps at 12:03:04)", at that moment
        /// "12:03:04": the stop was pressed then, while disconnected, and went out when the
        /// link came back; empty: it went out when pressed.
        QString pressedWhileDisconnectedAt;
    };
    /// The bus's account of the stop.
    struct Outcome {
        QVector<int> acknowledged, silent;
        QVector<int> unsent; ///< of the silent, those the halt never went out to
        int remaining = 0;   ///< > 0: the stop is under way, this many IDs still to come
        /// Watched drives that were not seen to stop, which a state read has since shown
        /// stopped: no longer said to be possibly moving.
        QVector<int> sinceStopped;
    };
    struct Text {
        MessageBanner::Level level = MessageBanner::Level::Info;
        QString html;
    };

    static Text compose(const Context &context, const Outcome &outcome);
    /// The watched drives the report says may still be moving (not acknowledged, not seen
    /// stopped since); for a stop that sent nothing, every watched drive.
    static QVector<int> mayBeMoving(const Context &context, const Outcome &outcome);
};

} // namespace lk::ui
