#pragma once

#include <tuning/StepRun.h>

#include <QtCore/QObject>
#include <QtCore/QString>
#include <QtCore/QVector>

namespace lk::ui {

/// The step-test runs of this session, oldest first, each with whether it is overlaid. A run
/// of this session is numbered here, after every run the list holds; a loaded run keeps the
/// number and name it was saved with. Two runs may then share a number (two files may both
/// hold a "Run 1"), so the list tells its runs apart by a key of its own, and their titles
/// by the file a loaded run came from.
class StepRunList : public QObject {
    Q_OBJECT
public:
    explicit StepRunList(QObject *parent = nullptr);

    /// Adds a run of this session (numbered here, overlaid) and returns its key.
    int add(tuning::StepRun run);
    /// Adds a run read from `file` (overlaid) as it was saved: its number and name kept.
    /// Returns its key.
    int addLoaded(tuning::StepRun run, const QString &file);
    void remove(int key);
    void clear();
    const QVector<tuning::StepRun> &runs() const { return m_runs; }
    /// The key of the run at `index` (0 when out of range).
    int keyAt(int index) const;
    const tuning::StepRun *find(int key) const;
    int indexOf(int key) const;
    bool isShown(int key) const;
    void setShown(int key, bool shown);
    /// The overlaid runs, oldest first.
    QVector<tuning::StepRun> shownRuns() const;
    /// The keys of shownRuns(), in the same order.
    QVector<int> shownKeys() const;
    /// The run's name, else "Run 3"; a loaded run whose title another run also has gets its
    /// file's name after it.
    QString title(int index) const;

signals:
    void changed();

private:
    struct Entry {
        int key = 0;
        bool shown = true;
        QString file; ///< the file a loaded run came from; empty for this session's runs
    };
    int append(tuning::StepRun run, const QString &file);
    QString baseTitle(int index) const;

    QVector<tuning::StepRun> m_runs;
    QVector<Entry> m_entries; ///< per run, in the same order
    int m_nextKey = 1;
};

} // namespace lk::ui
