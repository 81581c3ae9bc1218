#pragma once

#include <tuning/StepRun.h>

#include <QtCore/QObject>
#include <QtCore/QVector>

namespace lk::ui {

/// The step-test runs of this session, oldest first, each with whether it is overlaid. Runs
/// are numbered in the order they were added (loaded runs get new numbers: two files may both
/// hold a "Run 1").
class StepRunList : public QObject {
    Q_OBJECT
public:
    explicit StepRunList(QObject *parent = nullptr);

    /// Adds a run (numbered here, overlaid) and returns its number.
    int add(tuning::StepRun run);
    void remove(int number);
    void clear();
    const QVector<tuning::StepRun> &runs() const { return m_runs; }
    const tuning::StepRun *find(int number) const;
    int indexOf(int number) const;
    bool isShown(int number) const;
    void setShown(int number, bool shown);
    /// The overlaid runs, oldest first.
    QVector<tuning::StepRun> shownRuns() const;

signals:
    void changed();

private:
    QVector<tuning::StepRun> m_runs;
    QVector<bool> m_shown;
    int m_nextNumber = 1;
};

} // namespace lk::ui
