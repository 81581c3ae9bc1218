#include "StepRunList.h"

#include <QtCore/QFileInfo>

#include <algorithm>

namespace lk::ui {

StepRunList::StepRunList(QObject *parent) : QObject(parent) {}

int StepRunList::add(tuning::StepRun run)
{
    // After every number held, loaded runs' included: a new run never takes a shown number.
    int highest = 0;
    for (const tuning::StepRun &r : std::as_const(m_runs))
        highest = std::max(highest, r.number);
    run.number = highest + 1;
    return append(std::move(run), {});
}

int StepRunList::addLoaded(tuning::StepRun run, const QString &file)
{
    return append(std::move(run), QFileInfo(file).fileName());
}

int StepRunList::append(tuning::StepRun run, const QString &file)
{
    m_runs.append(std::move(run));
    m_entries.append(Entry{m_nextKey++, true, file});
    emit changed();
    return m_entries.last().key;
}

void StepRunList::remove(int key)
{
    const int i = indexOf(key);
    if (i < 0)
        return;
    m_runs.removeAt(i);
    m_entries.removeAt(i);
    emit changed();
}

void StepRunList::clear()
{
    if (m_runs.isEmpty())
        return;
    m_runs.clear();
    m_entries.clear();
    emit changed();
}

int StepRunList::keyAt(int index) const
{
    return index >= 0 && index < m_entries.size() ? m_entries.at(index).key : 0;
}

int StepRunList::indexOf(int key) const
{
    for (int i = 0; i < m_entries.size(); ++i) {
        if (m_entries.at(i).key == key)
            return i;
    }
    return -1;
}

const tuning::StepRun *StepRunList::find(int key) const
{
    const int i = indexOf(key);
    return i < 0 ? nullptr : &m_runs.at(i);
}

bool StepRunList::isShown(int key) const
{
    const int i = indexOf(key);
    return i >= 0 && m_entries.at(i).shown;
}

void StepRunList::setShown(int key, bool shown)
{
    const int i = indexOf(key);
    if (i < 0 || m_entries.at(i).shown == shown)
        return;
    m_entries[i].shown = shown;
    emit changed();
}

QVector<tuning::StepRun> StepRunList::shownRuns() const
{
    QVector<tuning::StepRun> out;
    for (int i = 0; i < m_runs.size(); ++i) {
        if (m_entries.at(i).shown)
            out.append(m_runs.at(i));
    }
    return out;
}

QVector<int> StepRunList::shownKeys() const
{
    QVector<int> out;
    for (const Entry &e : m_entries) {
        if (e.shown)
            out.append(e.key);
    }
    return out;
}

QString StepRunList::baseTitle(int index) const
{
    const tuning::StepRun &run = m_runs.at(index);
    return run.label.isEmpty() ? tr("Run %1").arg(run.number) : run.label;
}

QString StepRunList::title(int index) const
{
    if (index < 0 || index >= m_runs.size())
        return {};
    const QString base = baseTitle(index);
    const QString &file = m_entries.at(index).file;
    if (file.isEmpty())
        return base;
    for (int i = 0; i < m_runs.size(); ++i) {
        if (i != index && baseTitle(i) == base)
            return tr("%1 (%2)").arg(base, file);
    }
    return base;
}

} // namespace lk::ui
