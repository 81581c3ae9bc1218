#include "StepRunList.h"

namespace lk::ui {

StepRunList::StepRunList(QObject *parent) : QObject(parent) {}

int StepRunList::add(tuning::StepRun run)
{
    run.number = m_nextNumber++;
    m_runs.append(std::move(run));
    m_shown.append(true);
    emit changed();
    return m_runs.last().number;
}

void StepRunList::remove(int number)
{
    const int i = indexOf(number);
    if (i < 0)
        return;
    m_runs.removeAt(i);
    m_shown.removeAt(i);
    emit changed();
}

void StepRunList::clear()
{
    if (m_runs.isEmpty())
        return;
    m_runs.clear();
    m_shown.clear();
    emit changed();
}

int StepRunList::indexOf(int number) const
{
    for (int i = 0; i < m_runs.size(); ++i) {
        if (m_runs.at(i).number == number)
            return i;
    }
    return -1;
}

const tuning::StepRun *StepRunList::find(int number) const
{
    const int i = indexOf(number);
    return i < 0 ? nullptr : &m_runs.at(i);
}

bool StepRunList::isShown(int number) const
{
    const int i = indexOf(number);
    return i >= 0 && m_shown.at(i);
}

void StepRunList::setShown(int number, bool shown)
{
    const int i = indexOf(number);
    if (i < 0 || m_shown.at(i) == shown)
        return;
    m_shown[i] = shown;
    emit changed();
}

QVector<tuning::StepRun> StepRunList::shownRuns() const
{
    QVector<tuning::StepRun> out;
    for (int i = 0; i < m_runs.size(); ++i) {
        if (m_shown.at(i))
            out.append(m_runs.at(i));
    }
    return out;
}

} // namespace lk::ui
