#include "EncoderLiveBox.h"

#include "EncoderDial.h"
#include "EncoderResolutions.h"

#include <QtWidgets/QFormLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace lk::ui {

namespace {
QLabel *readout(const QString &name, QWidget *parent)
{
    auto *l = new QLabel(QStringLiteral("\u2013"), parent);
    l->setObjectName(name);
    l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont f = l->font();
    f.setPointSizeF(f.pointSizeF() * 1.25);
    f.setBold(true);
    l->setFont(f);
    // "43388 of 65536 (16-bit, from data)  (238.33°)" must not widen the view past a small
    // screen: it wraps instead.
    l->setWordWrap(true);
    return l;
}
} // namespace

EncoderLiveBox::EncoderLiveBox(QWidget *parent)
    : QGroupBox(tr("Live (read while this view is shown)"), parent),
      m_encoder(readout(QStringLiteral("encoderValue"), this)),
      m_raw(readout(QStringLiteral("encoderRaw"), this)),
      m_offset(readout(QStringLiteral("encoderOffset"), this)),
      m_multi(readout(QStringLiteral("multiTurn"), this)),
      m_output(readout(QStringLiteral("outputShaft"), this)),
      m_single(readout(QStringLiteral("singleTurn"), this)), m_dial(new EncoderDial(this))
{
    auto *form = new QFormLayout;
    form->addRow(tr("Encoder (raw \u2212 offset):"), m_encoder);
    form->addRow(tr("Raw encoder:"), m_raw);
    form->addRow(tr("Encoder offset:"), m_offset);
    form->addRow(tr("Multi-turn angle (rotor):"), m_multi);
    form->addRow(tr("Output shaft:"), m_output);
    form->addRow(tr("Single-turn angle:"), m_single);
    auto *legend = new QLabel(tr("Dial: the blue needle is the raw position, the red mark the "
                                 "offset (where the encoder reads 0); the centre shows the "
                                 "encoder angle."),
                              this);
    legend->setWordWrap(true);
    auto *column = new QVBoxLayout(this);
    column->addLayout(form);
    column->addWidget(m_dial, 1);
    column->addWidget(legend);
}

bool EncoderLiveBox::anglesDisagree(const std::optional<protocol::EncoderReading> &encoder,
                                    const std::optional<double> &singleTurnDeg,
                                    const motor::EncoderResolution &resolution, double ratio)
{
    using Source = motor::EncoderResolution::Source;
    // Both start at the encoder zero: without a gearbox they name the same angle of the rotor.
    if (!encoder || !singleTurnDeg || ratio != 1.0)
        return false;
    const Source source = resolution.source();
    if (source == Source::Name || source == Source::Generation || source == Source::User)
        return false; // known: a difference is a zero moved since (0x95), not the resolution
    const double deg = 360.0 * encoder->encoder / resolution.countsPerTurn();
    const double apart = std::fmod(std::fabs(deg - *singleTurnDeg), 360.0);
    return std::min(apart, 360.0 - apart) > kAgreeDeg;
}

void EncoderLiveBox::setValues(const std::optional<protocol::EncoderReading> &encoder,
                               const std::optional<double> &multiTurnDeg,
                               const std::optional<double> &singleTurnDeg,
                               const motor::EncoderResolution &resolution, double ratio)
{
    const QString none = QStringLiteral("\u2013");
    const int counts = resolution.countsPerTurn();
    // Two angles for one shaft, one of them from a resolution only assumed: the encoder's
    // degrees are left out rather than shown beside the single-turn angle they contradict.
    const bool unsure = anglesDisagree(encoder, singleTurnDeg, resolution, ratio);
    auto countText = [counts, unsure](int v) {
        return unsure ? QString::number(v)
                      : tr("%1  (%2\u00b0)").arg(v).arg(360.0 * v / counts, 0, 'f', 2);
    };
    auto degText = [](double deg) { return tr("%1\u00b0").arg(deg, 0, 'f', 2); };
    // The encoder reads as on the dashboard: value, counts per turn, and where the resolution
    // comes from.
    const QString reading =
        encoder ? EncoderResolutions::readoutText(encoder->encoder, resolution) : QString();
    m_encoder->setText(
        !encoder ? none
        : unsure
            ? tr("%1  (no angle: the single-turn angle disagrees, so the "
                 "resolution is not known yet)")
                  .arg(reading)
            : tr("%1  (%2\u00b0)").arg(reading).arg(360.0 * encoder->encoder / counts, 0, 'f', 2));
    m_raw->setText(encoder ? countText(encoder->encoderRaw) : none);
    m_offset->setText(encoder ? countText(encoder->encoderOffset) : none);
    m_multi->setText(multiTurnDeg ? degText(*multiTurnDeg) : none);
    m_output->setText(
        multiTurnDeg ? tr("%1 (\u00f7 %2)").arg(degText(*multiTurnDeg / ratio)).arg(ratio) : none);
    m_single->setText(singleTurnDeg ? degText(*singleTurnDeg) : none);
    m_dial->setReading(encoder ? std::optional<int>(encoder->encoder) : std::nullopt,
                       encoder ? std::optional<int>(encoder->encoderRaw) : std::nullopt,
                       encoder ? std::optional<int>(encoder->encoderOffset) : std::nullopt, counts);
}

} // namespace lk::ui
