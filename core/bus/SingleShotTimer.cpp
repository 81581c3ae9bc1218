#include "SingleShotTimer.h"

#include <QtCore/QPointer>
#include <QtCore/QTimer>

namespace lk::bus {

namespace {
/// SingleShotTimer on a QTimer that is a child of the owner: it lives on the owner's thread.
class QtSingleShotTimer final : public SingleShotTimer {
public:
    QtSingleShotTimer(QObject *owner, std::function<void()> onTimeout) : m_timer(new QTimer(owner))
    {
        m_timer->setSingleShot(true);
        m_timer->setTimerType(Qt::PreciseTimer); // a coarse timer may be 5 % late
        QObject::connect(m_timer, &QTimer::timeout, owner, std::move(onTimeout));
    }
    ~QtSingleShotTimer() override { delete m_timer.data(); } // null if the owner went first
    void start(int ms) override { m_timer->start(ms); }
    void stop() override { m_timer->stop(); }
    bool isActive() const override { return m_timer->isActive(); }

private:
    QPointer<QTimer> m_timer;
};
} // namespace

std::unique_ptr<SingleShotTimer> makeQtSingleShotTimer(QObject *owner,
                                                       std::function<void()> onTimeout)
{
    return std::make_unique<QtSingleShotTimer>(owner, std::move(onTimeout));
}

} // namespace lk::bus
