#include "BlackBoxTrafficFeed.h"

#include "BlackBoxRecorder.h"

#include <panels/TrafficPanel.h>

#include <QtCore/QTimer>

namespace lk::ui {

namespace {
constexpr int kFollowMs = 100; // as the panel's own flush
} // namespace

BlackBoxTrafficFeed::BlackBoxTrafficFeed(BlackBoxRecorder *recorder, TrafficPanel *panel,
                                         QObject *parent)
    : QObject(parent), m_recorder(recorder), m_panel(panel), m_timer(new QTimer(this))
{
    m_timer->setInterval(kFollowMs);
    connect(m_timer, &QTimer::timeout, this, &BlackBoxTrafficFeed::follow);
    connect(panel, &TrafficPanel::captureWanted, this, &BlackBoxTrafficFeed::setLooking);
    connect(recorder, &BlackBoxRecorder::ringStarted, this, [this] {
        if (m_looking && !m_suspended)
            reload();
    });
    setLooking(panel->wantsCapture());
}

void BlackBoxTrafficFeed::setSuspended(bool on)
{
    m_suspended = on;
    setLooking(m_looking);
}

void BlackBoxTrafficFeed::setLooking(bool on)
{
    m_looking = on;
    const bool feed = on && !m_suspended;
    m_recorder->tap()->setEnabled(feed);
    if (feed) {
        reload();
        m_timer->start();
    } else {
        m_timer->stop();
    }
}

void BlackBoxTrafficFeed::reload()
{
    // The tap first: whatever arrives while the ring is read is in one or the other, and
    // what is in both is told by its time.
    m_recorder->tap()->setEnabled(true);
    recording::ContextSnapshot context;
    QVector<recording::RecordEvent> records;
    protocol::Link link = protocol::Link::Rs485;
    if (const auto box = m_recorder->box()) {
        records = box->events(&context);
        link = recording::linkOf(box->header());
    }
    m_shownUntilNs = records.isEmpty() ? -1 : records.constLast().timeNs;
    m_converter = RecordTrafficConverter(context, link);
    m_panel->showTraffic(m_converter.convert(records));
}

void BlackBoxTrafficFeed::follow()
{
    bool overflowed = false;
    QVector<recording::RecordEvent> records = m_recorder->tap()->take(&overflowed);
    if (overflowed) {
        reload();
        return;
    }
    records.removeIf(
        [this](const recording::RecordEvent &r) { return r.timeNs <= m_shownUntilNs; });
    if (!records.isEmpty())
        m_panel->appendTraffic(m_converter.convert(records));
}

} // namespace lk::ui
