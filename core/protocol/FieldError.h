#pragma once

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

namespace lk::protocol {

/// Why a value was refused: names the field (CLI.md spelling) and its allowed range.
struct FieldError {
    QString field;   ///< e.g. "iq_a"
    QString range;   ///< e.g. "-32..32 A"
    QString problem; ///< optional detail, e.g. "got 40"
    QString message() const
    {
        QString m = QCoreApplication::translate("lk::protocol::FieldError", "%1 must be in %2")
                        .arg(field, range);
        if (!problem.isEmpty())
            m += QStringLiteral(" (%1)").arg(problem);
        return m;
    }
};

} // namespace lk::protocol
