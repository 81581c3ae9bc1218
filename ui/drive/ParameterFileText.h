#pragma once

#include <record/ParameterSet.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

namespace lk::ui {

/// Words a refused parameter file (record::ParameterFileError) for the user: the key, what it
/// must hold (type and range) and what the file has there.
class ParameterFileText {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::ParameterFileText)
public:
    /// "pid.iq_kp is 256: it must be an integer in 0..255", ...
    static QString describe(const record::ParameterFileError &error);
    /// "an integer in 0..255", "text", ...
    static QString expectation(const record::ParameterFileError &error);
};

} // namespace lk::ui
