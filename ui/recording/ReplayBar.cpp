#include "ReplayBar.h"

#include "RecordingReplay.h"

#include <QtCore/QFileInfo>
#include <QtCore/QTimer>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QSlider>
#include <QtWidgets/QToolButton>

namespace lk::ui {

namespace {
constexpr int kUpdateMs = 200;
constexpr int kSliderSteps = 1000; // per second of recording: the slider moves in ms
const double kSpeeds[] = {0.25, 0.5, 1, 2, 5, 10, 20};

QString clockText(double seconds)
{
    const int s = int(seconds);
    return QStringLiteral("%1:%2.%3")
        .arg(s / 60)
        .arg(s % 60, 2, 10, QLatin1Char('0'))
        .arg(int((seconds - s) * 10));
}
} // namespace

ReplayBar::ReplayBar(RecordingReplay *replay, QWidget *parent)
    : QToolBar(tr("Replay"), parent), m_replay(replay), m_timer(new QTimer(this))
{
    setObjectName(QStringLiteral("replayBar"));
    m_name = new QLabel(this);
    m_play = new QToolButton(this);
    m_play->setObjectName(QStringLiteral("replayPlay"));
    m_speed = new QComboBox(this);
    m_speed->setObjectName(QStringLiteral("replaySpeed"));
    m_speed->setToolTip(tr("Replay speed; idle gaps longer than a second are shortened"));
    for (double s : kSpeeds)
        m_speed->addItem(QStringLiteral("%1x").arg(s), s);
    m_speed->setCurrentIndex(2);
    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setObjectName(QStringLiteral("replaySeek"));
    m_slider->setMinimumWidth(200);
    m_position = new QLabel(this);
    m_position->setObjectName(QStringLiteral("replayPosition"));
    addWidget(m_name);
    addWidget(m_play);
    addWidget(m_speed);
    addWidget(m_slider);
    addWidget(m_position);
    QAction *all = addAction(tr("Load all"), m_replay, &RecordingReplay::loadAll);
    all->setObjectName(QStringLiteral("replayLoadAll"));
    all->setToolTip(tr("Read the rest of the recording at once: the plots show all of it"));
    QAction *close = addAction(tr("Close recording"), this, &ReplayBar::closeRequested);
    close->setObjectName(QStringLiteral("replayClose"));

    connect(m_play, &QToolButton::clicked, this, [this] {
        if (m_replay->isPaused())
            m_replay->play();
        else
            m_replay->pause();
        update();
    });
    connect(m_speed, qOverload<int>(&QComboBox::currentIndexChanged), this,
            [this] { m_replay->setSpeed(m_speed->currentData().toDouble()); });
    connect(m_slider, &QSlider::sliderReleased, this,
            [this] { m_replay->seek(double(m_slider->value()) / kSliderSteps); });
    m_timer->setInterval(kUpdateMs);
    connect(m_timer, &QTimer::timeout, this, &ReplayBar::update);
    refresh();
}

void ReplayBar::refresh()
{
    const bool open = m_replay->isOpen();
    setVisible(open);
    if (!open) {
        m_timer->stop();
        return;
    }
    m_name->setText(QFileInfo(m_replay->path()).fileName());
    m_name->setToolTip(m_replay->path());
    m_slider->setRange(0, int(m_replay->durationSeconds() * kSliderSteps));
    m_replay->setSpeed(m_speed->currentData().toDouble());
    m_timer->start();
    update();
}

void ReplayBar::update()
{
    m_play->setText(m_replay->isPaused() ? tr("Play") : tr("Pause"));
    if (!m_slider->isSliderDown())
        m_slider->setValue(int(m_replay->positionSeconds() * kSliderSteps));
    m_position->setText(
        tr("%1 of %2")
            .arg(clockText(m_replay->positionSeconds()), clockText(m_replay->durationSeconds())));
}

} // namespace lk::ui
