#pragma once

#include <QtWidgets/QWidget>

#include <optional>

namespace lk::ui {

/// A dial of one encoder turn in raw counts (0 at the top, clockwise as the drive counts):
/// the needle is the raw position, a red mark the offset (where the encoder reads 0), and the
/// centre shows the encoder angle (raw minus offset). It only draws what it is given.
class EncoderDial : public QWidget {
    Q_OBJECT
public:
    explicit EncoderDial(QWidget *parent = nullptr);

    /// Positions in counts of `countsPerTurn`; nullopt: nothing read yet.
    void setReading(std::optional<int> encoder, std::optional<int> raw, std::optional<int> offset,
                    int countsPerTurn);
    QSize sizeHint() const override { return {220, 220}; }
    QSize minimumSizeHint() const override { return {150, 150}; }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    std::optional<int> m_encoder, m_raw, m_offset;
    int m_counts = 16384;
};

} // namespace lk::ui
