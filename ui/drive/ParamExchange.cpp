#include "ParamExchange.h"

#include "DriveText.h"
#include "RequestTracker.h"

namespace lk::ui {

ParamExchange::ParamExchange(RequestTracker *tracker, QObject *parent)
    : QObject(parent), m_tracker(tracker)
{
}

void ParamExchange::setSpec(const ParamSetSpec *spec)
{
    m_spec = spec;
    clear();
}

void ParamExchange::clear()
{
    m_held = HeldValues(m_spec ? m_spec->fields().size() : 0);
    m_replies.clear();
    m_sent.reset();
    m_writeFailures.clear();
    m_readFailure.clear();
}

void ParamExchange::forgetOutstanding()
{
    m_outstanding = 0;
}

void ParamExchange::read(int id)
{
    if (!m_spec)
        return;
    m_readFailure.clear();
    m_replies.clear();
    const QVector<protocol::Request> requests = m_spec->reads(id);
    m_outstanding += int(requests.size());
    for (const protocol::Request &request : requests) {
        m_tracker->send(request, [this, id](const bus::RequestResult &r) {
            if (r.ok() && r.reply)
                m_replies << *r.reply;
            else
                m_readFailure = DriveText::failure(r);
            if (--m_outstanding > 0)
                return;
            m_outstanding = 0;
            m_held = m_spec->decode(m_replies); // what is not answered now is not known
            if (!complete() && m_readFailure.isEmpty())
                m_readFailure = tr("the drive's replies did not carry every value.");
            emit readFinished(id);
        });
    }
}

QString ParamExchange::write(int id, const ParamValues &values, bool rom)
{
    const std::optional<ParamValues> held = ParamSetSpec::known(m_held);
    if (!m_spec || !held)
        return tr("the drive's values have not been read.");
    if (rom && m_spec->ramOnly()) // the last gate before the bus: nothing goes to ROM
        return m_spec->texts().romTip;
    const QVector<ParamWrite> frames = m_spec->writes(id, values, *held, rom);
    if (frames.isEmpty())
        return tr("the pending edit does not differ from what the drive holds.");
    for (const ParamWrite &frame : frames) {
        if (!frame.built.ok())
            return DriveText::fieldError(frame.built.error); // nothing sent
    }
    SentValues sent{rom, values, {}};
    m_writeFailures.clear();
    for (const ParamWrite &frame : frames) {
        for (int f : frame.fields) {
            if (!sent.fields.contains(f))
                sent.fields << f;
        }
        const bool flash = rom && frame.built.request->command != protocol::Command::WriteAccelRam;
        // A flash write is sent exactly once: a lost reply is reported, never retried.
        m_tracker->send(
            *frame.built.request,
            [this, id, frame, values](const bus::RequestResult &r) {
                onWriteResult(id, frame, values, r);
            },
            bus::Priority::Operator, flash ? 0 : -1);
    }
    m_sent = sent;
    read(id);
    return QString();
}

void ParamExchange::onWriteResult(int id, const ParamWrite &frame, const ParamValues &values,
                                  const bus::RequestResult &r)
{
    const protocol::Command command = frame.built.request->command;
    if (!r.ok()) {
        m_writeFailures << tr("%1 (%2) of drive %3: %4")
                               .arg(fieldNames(frame.fields), DriveText::command(command))
                               .arg(id)
                               .arg(DriveText::failure(r));
        return;
    }
    const auto *result =
        r.reply ? std::get_if<protocol::ParamWriteResult>(&r.reply->payload) : nullptr;
    if (result && !result->succeeded()) {
        m_writeFailures << tr("drive %1 refused the write of %2 (%3 answered with failure flag "
                              "%4 for ParamID 0x%5).")
                               .arg(id)
                               .arg(fieldNames(frame.fields), DriveText::command(command))
                               .arg(result->flag)
                               .arg(result->paramId, 2, 16, QLatin1Char('0'));
        return;
    }
    if (command == protocol::Command::WritePidRom || command == protocol::Command::WriteParamRom)
        emit romWritten(id, values, frame.fields);
    else if (command == protocol::Command::WritePidRam ||
             command == protocol::Command::WriteParamRam ||
             command == protocol::Command::WriteControlParam)
        emit ramWritten(id);
}

QString ParamExchange::fieldNames(const QVector<int> &fields) const
{
    const QVector<ParamField> all = m_spec->fields();
    QStringList names;
    for (int f : fields)
        names << all.value(f).name;
    return names.join(QStringLiteral(", "));
}

std::optional<SentValues> ParamExchange::takeSent()
{
    std::optional<SentValues> sent = m_sent;
    m_sent.reset();
    return sent;
}

} // namespace lk::ui
