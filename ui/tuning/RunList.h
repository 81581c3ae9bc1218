#pragma once

#include <QtCore/QCoreApplication>
#include <QtCore/QFileInfo>
#include <QtCore/QObject>
#include <QtCore/QString>
#include <QtCore/QVector>

#include <algorithm>

namespace lk::ui {

/// The signal of a RunList (a class template cannot declare signals itself).
class RunListSignals : public QObject {
    Q_OBJECT
public:
    explicit RunListSignals(QObject *parent = nullptr) : QObject(parent) {}

signals:
    void changed();
};

/// The runs of a kind (step tests, frequency sweeps) kept in this session, oldest first, each
/// with whether it is overlaid. A run of this session is numbered here, after every run the
/// list holds; a loaded run keeps the number and name it was saved with. Two runs may then
/// share a number (two files may both hold a "Run 1"), so the list tells its runs apart by a
/// key of its own, and their titles by the file a loaded run came from. `Run` has an
/// `int number` and a `QString label`.
template <typename Run> class RunList : public RunListSignals {
public:
    using RunListSignals::RunListSignals;

    /// Adds a run of this session (numbered here, overlaid) and returns its key.
    int add(Run run)
    {
        // After every number held, loaded runs' included: a new run never takes a shown number.
        int highest = 0;
        for (const Run &r : std::as_const(m_runs))
            highest = std::max(highest, r.number);
        run.number = highest + 1;
        return append(std::move(run), {});
    }
    /// Adds a run read from `file` (overlaid) as it was saved: its number and name kept.
    /// Returns its key.
    int addLoaded(Run run, const QString &file)
    {
        return append(std::move(run), QFileInfo(file).fileName());
    }
    void remove(int key)
    {
        const int i = indexOf(key);
        if (i < 0)
            return;
        m_runs.removeAt(i);
        m_entries.removeAt(i);
        emit changed();
    }
    void clear()
    {
        if (m_runs.isEmpty())
            return;
        m_runs.clear();
        m_entries.clear();
        emit changed();
    }
    const QVector<Run> &runs() const { return m_runs; }
    /// The key of the run at `index` (0 when out of range).
    int keyAt(int index) const
    {
        return index >= 0 && index < m_entries.size() ? m_entries.at(index).key : 0;
    }
    const Run *find(int key) const
    {
        const int i = indexOf(key);
        return i < 0 ? nullptr : &m_runs.at(i);
    }
    int indexOf(int key) const
    {
        for (int i = 0; i < m_entries.size(); ++i) {
            if (m_entries.at(i).key == key)
                return i;
        }
        return -1;
    }
    bool isShown(int key) const
    {
        const int i = indexOf(key);
        return i >= 0 && m_entries.at(i).shown;
    }
    void setShown(int key, bool shown)
    {
        const int i = indexOf(key);
        if (i < 0 || m_entries.at(i).shown == shown)
            return;
        m_entries[i].shown = shown;
        emit changed();
    }
    /// The overlaid runs, oldest first.
    QVector<Run> shownRuns() const
    {
        QVector<Run> out;
        for (int i = 0; i < m_runs.size(); ++i) {
            if (m_entries.at(i).shown)
                out.append(m_runs.at(i));
        }
        return out;
    }
    /// The keys of shownRuns(), in the same order.
    QVector<int> shownKeys() const
    {
        QVector<int> out;
        for (const Entry &e : m_entries) {
            if (e.shown)
                out.append(e.key);
        }
        return out;
    }
    /// The run's name, else "Run 3"; a loaded run whose title another run also has gets its
    /// file's name after it.
    QString title(int index) const
    {
        if (index < 0 || index >= m_runs.size())
            return {};
        const QString base = baseTitle(index);
        const QString &file = m_entries.at(index).file;
        if (file.isEmpty())
            return base;
        for (int i = 0; i < m_runs.size(); ++i) {
            if (i != index && baseTitle(i) == base)
                return QCoreApplication::translate("lk::ui::StepRunList", "%1 (%2)")
                    .arg(base, file);
        }
        return base;
    }

private:
    struct Entry {
        int key = 0;
        bool shown = true;
        QString file; ///< the file a loaded run came from; empty for this session's runs
    };
    int append(Run run, const QString &file)
    {
        m_runs.append(std::move(run));
        m_entries.append(Entry{m_nextKey++, true, file});
        emit changed();
        return m_entries.last().key;
    }
    QString baseTitle(int index) const
    {
        const Run &run = m_runs.at(index);
        // The step runs' context: their translations predate the other kinds of run.
        return run.label.isEmpty()
                   ? QCoreApplication::translate("lk::ui::StepRunList", "Run %1").arg(run.number)
                   : run.label;
    }

    QVector<Run> m_runs;
    QVector<Entry> m_entries; ///< per run, in the same order
    int m_nextKey = 1;
};

} // namespace lk::ui
