#include "RecordingController.h"

#include "BlackBoxRecorder.h"
#include "BlackBoxTrafficFeed.h"

#include <main/BusController.h>
#include <panels/MessageBanner.h>

#include <QtWidgets/QMenu>

namespace lk::ui {

namespace {
const QString kOnRequest = QStringLiteral("on request");

recording::RecordingHeader headerFor(const ConnectionChoice &choice)
{
    recording::RecordingHeader h;
    h.linkKind =
        choice.isSimulator() ? recording::LinkKind::Simulated : recording::LinkKind::Serial;
    h.linkDescription = QStringLiteral("%1 @ %2")
                            .arg(choice.isSimulator() ? QStringLiteral("simulator") : choice.port)
                            .arg(choice.baud);
    h.baud = choice.baud;
    return h;
}
} // namespace

RecordingController::RecordingController(BusController *controller, TrafficPanel *traffic,
                                         MessageBanner *banner, QObject *parent)
    : QObject(parent), m_controller(controller), m_banner(banner),
      m_recorder(new BlackBoxRecorder(this)),
      m_feed(new BlackBoxTrafficFeed(m_recorder, traffic, this))
{
    controller->setFactoryWrapper(
        [this](bus::TransportFactory inner, const ConnectionChoice &choice) {
            return m_recorder->wrap(std::move(inner), headerFor(choice));
        });
    m_recorder->attach(controller->session());
    connect(m_recorder, &BlackBoxRecorder::saved, this, &RecordingController::showSaved);
    connect(m_recorder, &BlackBoxRecorder::saveFailed, this, &RecordingController::showSaveFailed);
}

void RecordingController::addFileActions(QMenu *file)
{
    m_save = file->addAction(tr("Save the last %n minute(s)", nullptr, m_recorder->windowMinutes()),
                             this, &RecordingController::saveNow);
    m_save->setObjectName(QStringLiteral("saveBlackBox"));
    m_save->setToolTip(tr("Write what the black box holds to %1").arg(m_recorder->folder()));
}

void RecordingController::saveNow()
{
    m_recorder->save(kOnRequest);
}

QString RecordingController::causeText(const QString &why)
{
    if (why == QLatin1String("emergency stop"))
        return tr("the emergency stop");
    if (why == QLatin1String("fault flag"))
        return tr("a new drive fault flag");
    if (why == QLatin1String("link lost"))
        return tr("the link loss");
    if (why == QLatin1String("timeout burst"))
        return tr("a burst of timeouts");
    return tr("your request");
}

void RecordingController::showSaved(const QString &why, const QString &path)
{
    m_banner->setEntry(entryKey(), MessageBanner::Level::Info,
                       tr("Black box saved after %1: the last %n minute(s) of the link are in "
                          "%2",
                          nullptr, m_recorder->windowMinutes())
                           .arg(causeText(why).toHtmlEscaped(), path.toHtmlEscaped()));
}

void RecordingController::showSaveFailed(const QString &why, const QString &error)
{
    m_banner->setEntry(entryKey(), MessageBanner::Level::Warning,
                       tr("The black box could not be saved after %1: %2")
                           .arg(causeText(why).toHtmlEscaped(), error.toHtmlEscaped()));
}

} // namespace lk::ui
