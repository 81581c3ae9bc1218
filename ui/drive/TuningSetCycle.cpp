#include "TuningSetCycle.h"

#include "ConfirmDialog.h"
#include "ParamExchange.h"
#include "ParameterTable.h"
#include "RequestTracker.h"
#include "TuningText.h"

namespace lk::ui {

TuningSetCycle::TuningSetCycle(DriveView *view, RequestTracker *tracker, ParameterTable *table)
    : QObject(view), m_view(view), m_tracker(tracker), m_table(table),
      m_exchange(new ParamExchange(tracker, this))
{
    connect(m_exchange, &ParamExchange::readFinished, this, &TuningSetCycle::onReadDone);
    connect(m_exchange, &ParamExchange::romWritten, this, &TuningSetCycle::onRomWritten);
    connect(m_exchange, &ParamExchange::ramWritten, this,
            [this](int id) { m_memory[id].ramWritten = true; });
}

void TuningSetCycle::setSpec(const ParamSetSpec *spec)
{
    m_spec = spec;
    m_exchange->setSpec(spec);
}

bool TuningSetCycle::isBusy() const
{
    return m_tracker->pendingCount() > 0;
}

HeldValues TuningSetCycle::held() const
{
    return m_exchange->held();
}

std::optional<QTime> TuningSetCycle::firstReadAt() const
{
    const DriveMemory mem = m_memory.value(m_view->driveId());
    return mem.firstRead ? std::optional<QTime>(mem.firstReadAt) : std::nullopt;
}

void TuningSetCycle::setStatus(const QString &text, bool error)
{
    m_status = text;
    emit statusChanged(text, error);
}

void TuningSetCycle::contextChanged(DriveView::Changes changes)
{
    using Change = DriveView::Change;
    const bool linkDown = (changes & Change::Connection) && !m_view->isConnected();
    // What was read belongs to one connection: the next one may reach other drives. What was
    // written stays for the session (the RAM/ROM warning errs on the side of caution).
    if (changes & Change::Session) {
        m_memory.clear();
    } else if (linkDown) {
        for (DriveMemory &mem : m_memory) {
            mem.firstRead.reset();
            mem.unsentEdit.reset();
        }
    } else if (changes & Change::Drive) {
        keepUnsentEdit();
    }
    if (m_tracker->pendingCount() == 0)
        m_exchange->forgetOutstanding(); // the tracker forgot them with the drive or the link
    if (changes & (Change::Session | Change::Drive | Change::Connection))
        m_readComplete = false;
}

void TuningSetCycle::startOver()
{
    forgetOtherGeneration();
    m_exchange->clear();
    emit mismatchChanged(QString());
    m_table->setHolds(m_exchange->held());
    m_table->clearPending(); // never another drive's (or connection's) values
    setStatus(QString());
}

void TuningSetCycle::showDrive()
{
    m_shownId = m_view->driveId();
    m_table->setOriginal(m_memory.value(m_shownId).firstRead);
}

void TuningSetCycle::forgetOtherGeneration()
{
    // An ID answered by a drive of the other generation is another drive.
    for (auto it = m_memory.begin(); it != m_memory.end();) {
        if (it.key() == m_view->driveId() && it->generation != m_spec->generation())
            it = m_memory.erase(it);
        else
            ++it;
    }
}

void TuningSetCycle::keepUnsentEdit()
{
    if (m_shownId <= 0 || !m_readComplete || !m_table->anyChanged())
        return;
    m_memory[m_shownId].unsentEdit = m_table->pending();
}

void TuningSetCycle::readFromDrive()
{
    if (!m_view->canSendToDrive() || isBusy())
        return;
    setStatus(QString());
    read(!m_table->pending() || !m_table->anyChanged());
}

void TuningSetCycle::read(bool takePending)
{
    m_takePending = takePending;
    m_exchange->read(m_view->driveId());
}

void TuningSetCycle::onReadDone(int id)
{
    if (id != m_view->driveId())
        return;
    m_readComplete = m_exchange->complete();
    DriveMemory &mem = m_memory[id];
    mem.generation = m_spec->generation();
    if (m_readComplete && !mem.firstRead) {
        mem.firstRead = ParamSetSpec::known(m_exchange->held());
        mem.firstReadAt = QTime::currentTime();
    }
    m_table->setOriginal(mem.firstRead);
    m_table->setHolds(m_exchange->held());
    if (m_readComplete)
        takeReadValues(mem);
    else if (m_takePending)
        m_table->clearPending(); // it showed the drive's values, which are not known now
    m_takePending = false;
    if (const std::optional<SentValues> sent = m_exchange->takeSent())
        checkReadBack(*sent);
    else if (!m_readComplete)
        setStatus(tr("Could not read drive %1: %2 Editing and writing stay off until every "
                     "value shown has been read; press Read from drive to try again.")
                      .arg(id)
                      .arg(m_exchange->readFailure()),
                  true);
    else if (m_status.isEmpty())
        setStatus(tr("Read from drive %1 at %2.")
                      .arg(id)
                      .arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss"))));
    emit readFinished(id);
}

void TuningSetCycle::takeReadValues(DriveMemory &mem)
{
    if (mem.unsentEdit) {
        m_table->setPending(*mem.unsentEdit);
        mem.unsentEdit.reset();
        setStatus(tr("Your unsent edit of drive %1 is back in the pending edit; values that "
                     "differ from the drive are highlighted.")
                      .arg(m_view->driveId()));
    } else if (m_takePending || !m_table->pending()) {
        m_table->setPending(*ParamSetSpec::known(m_exchange->held()));
    }
}

bool TuningSetCycle::mayWrite()
{
    if (!m_view->canSendToDrive() || isBusy())
        return false; // the buttons say so: disabled
    if (!m_readComplete) {
        setStatus(tr("Nothing was sent: the drive's values have not all been read on this "
                     "connection. Read from drive first."),
                  true);
        return false;
    }
    return true;
}

bool TuningSetCycle::confirmWrite(WriteKind kind, int id, const ParamValues &values)
{
    switch (kind) {
    case WriteKind::Ram:
        return true; // RAM is the place to try: lost at power-off
    case WriteKind::Rom:
        return ConfirmDialog::ask(m_view, m_spec->romQuestion(id, values));
    case WriteKind::RestoreFirstRead:
        return ConfirmDialog::ask(m_view, TuningText::restore(id, m_memory.value(id).firstReadAt,
                                                              m_spec->valuesText(values)));
    }
    return false;
}

void TuningSetCycle::write(WriteKind kind)
{
    if (!mayWrite())
        return;
    const int id = m_view->driveId();
    const std::optional<ParamValues> values =
        kind == WriteKind::RestoreFirstRead ? m_memory.value(id).firstRead : m_table->pending();
    if (!values)
        return; // no first read to restore, or no pending edit: nothing to write
    if (!confirmWrite(kind, id, *values)) {
        setStatus(kind == WriteKind::Rom ? tr("ROM write cancelled: nothing was sent.")
                                         : tr("Restore cancelled: nothing was sent."));
        return;
    }
    // The dialog ran an event loop: the drive, the link or the read may have changed meanwhile.
    if (!m_view->canSendToDrive() || m_view->driveId() != id || isBusy() || !m_readComplete) {
        setStatus(tr("The drive or the connection changed: nothing was sent."), true);
        return;
    }
    const bool rom = kind == WriteKind::Rom;
    m_takePending = false; // the read-back must not overwrite the pending edit
    const QString error = m_exchange->write(id, *values, rom);
    if (!error.isEmpty()) {
        setStatus(tr("Nothing was sent: %1").arg(error), true);
        return;
    }
    if (kind == WriteKind::RestoreFirstRead)
        m_table->setPending(*values);
    emit mismatchChanged(QString());
    setStatus(rom ? tr("Writing gains to the ROM of drive %1\u2026").arg(id)
                  : tr("Writing to the RAM of drive %1\u2026").arg(id));
    emit stateChanged();
}

void TuningSetCycle::onRomWritten(int id, const ParamValues &values, const QVector<int> &fields)
{
    DriveMemory &mem = m_memory[id];
    if (mem.lastRom != values)
        mem.romFields.clear();
    mem.lastRom = values;
    for (int f : fields) {
        if (!mem.romFields.contains(f))
            mem.romFields << f;
    }
    mem.ramWritten = false;
}

void TuningSetCycle::checkReadBack(const SentValues &sent)
{
    const HeldValues held = m_exchange->held();
    const QStringList problems = m_spec->readBackProblems(sent, held);
    if (!problems.isEmpty())
        emit mismatchChanged(problems.join(QLatin1Char('\n')));
    const QStringList failures = m_exchange->writeFailures();
    if (failures.isEmpty())
        emit writeAcknowledged(sent.rom);
    if (!failures.isEmpty())
        setStatus(tr("The write failed: %1").arg(failures.join(QLatin1Char(' '))), true);
    else if (!m_readComplete)
        setStatus(tr("Sent to drive %1, but the read-back did not complete (below).")
                      .arg(m_view->driveId()),
                  true);
    else if (!problems.isEmpty())
        setStatus(tr("Written, but the read-back differs (below)."), true);
    else
        setStatus(m_spec->written(sent, m_view->driveId()));
}

TuningSetCycle::RamRomNote TuningSetCycle::ramRomNote() const
{
    const DriveMemory mem = m_memory.value(m_view->driveId());
    const HeldValues held = m_exchange->held();
    bool differs = false;
    for (int f : mem.romFields) {
        const std::optional<qint64> v = held.value(f);
        differs = differs || (mem.lastRom && v && *v != mem.lastRom->value(f));
    }
    RamRomNote note;
    if (differs)
        note.text = tr("RAM gains differ from what was last written to ROM (%1): a power cycle "
                       "brings back the ROM values.")
                        .arg(m_spec->fieldsText(*mem.lastRom, mem.romFields));
    else if (!mem.lastRom && mem.ramWritten)
        note.text = tr("RAM gains were changed in this session and not written to ROM: they are "
                       "lost at power-off.");
    note.warning = m_view->hasDrive() && !note.text.isEmpty();
    if (!note.warning && m_view->hasDrive()) {
        if (mem.lastRom)
            note.text = tr("RAM holds the gains last written to ROM in this session.");
        else
            note.text = tr("Nothing written to this drive in this session: RAM holds what the "
                           "drive loaded from ROM at power-on (unless another tool changed it).");
    }
    return note;
}

} // namespace lk::ui
