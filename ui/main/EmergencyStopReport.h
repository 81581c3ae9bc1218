#pragma once

#include <panels/MessageBanner.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QStringList>
#include <QtCore/QVector>

namespace lk::ui {

/// The wording of one emergency stop's banner report, from what the bus said of it: who
/// acknowledged, who stayed silent, and which never got the halt on the wire. Pure, so each
/// case is tested without a bus.
class EmergencyStopReport {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::EmergencyStopReport)
public:
    /// The drives the stop had in mind when it began.
    struct Context {
        QVector<int> watched;  ///< known or commanded IDs
        QStringList commanded; ///< "Drive 2 (speed 360 dps at 12:03:04)", at that moment
    };
    /// The bus's account of the stop.
    struct Outcome {
        QVector<int> acknowledged, silent;
        QVector<int> unsent; ///< of the silent, those the halt never went out to
    };
    struct Text {
        MessageBanner::Level level = MessageBanner::Level::Info;
        QString html;
    };

    static Text compose(const Context &context, const Outcome &outcome);
};

} // namespace lk::ui
