#pragma once

#include <motor/EncoderResolution.h>
#include <protocol/Values.h>

#include <QtWidgets/QGroupBox>

#include <optional>

class QLabel;

namespace lk::ui {

class EncoderDial;

/// The live readouts of the encoder view: encoder, raw encoder and offset (counts and
/// degrees), multi-turn angle of the rotor and the output shaft, single-turn angle, and the
/// encoder dial. It shows what it is given; the view does the reading.
class EncoderLiveBox : public QGroupBox {
    Q_OBJECT
public:
    explicit EncoderLiveBox(QWidget *parent = nullptr);

    void setValues(const std::optional<protocol::EncoderReading> &encoder,
                   const std::optional<double> &multiTurnDeg,
                   const std::optional<double> &singleTurnDeg,
                   const motor::EncoderResolution &resolution, double gearRatio);
    /// How far (deg) the encoder's angle and the single-turn angle may differ and agree: the
    /// two come from reads a poll round apart.
    static constexpr double kAgreeDeg = 2.0;
    /// True when the encoder's angle at `resolution` contradicts the single-turn angle while
    /// the resolution is only assumed (series default, guess, data): it is then not shown.
    static bool anglesDisagree(const std::optional<protocol::EncoderReading> &encoder,
                               const std::optional<double> &singleTurnDeg,
                               const motor::EncoderResolution &resolution, double gearRatio);

private:
    QLabel *m_encoder;
    QLabel *m_raw;
    QLabel *m_offset;
    QLabel *m_multi;
    QLabel *m_output;
    QLabel *m_single;
    EncoderDial *m_dial;
};

} // namespace lk::ui
