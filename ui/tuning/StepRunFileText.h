#pragma once

#include <tuning/StepRunFile.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QString>

namespace lk::ui {

/// Words a refused step-run file (tuning::StepRunFileError) for the user: the file, the key or
/// line, what it must hold and what it has.
class StepRunFileText {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::StepRunFileText)
public:
    static QString describe(const tuning::StepRunFileError &error);

private:
    static QString expectation(const tuning::StepRunFileError &error);
};

} // namespace lk::ui
