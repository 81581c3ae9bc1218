#pragma once

#include <protocol/Series.h>

#include <QtCore/QSet>
#include <QtWidgets/QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace lk::ui {

class BusModel;

/// The series of the current drive, chosen by the user where the bus could not learn it (no
/// 0x12 model reply seen: a drive only listened to, or any drive on CAN, which has no model
/// read): MS, MF, MG or MH, and beside it the gear ratio, which the model name would have
/// given, and on CAN the generation (old or V2.36) where no reply told it. Shown while the
/// current drive's series (on CAN: or generation) is unknown or was chosen here; until then
/// an MS drive's power is not shown as current anywhere, and torque, power and open loop stay
/// refused (the motion checks' rule for an unknown series).
class SeriesChooser : public QWidget {
    Q_OBJECT
public:
    explicit SeriesChooser(BusModel *model, QWidget *parent = nullptr);

    /// Drive `id`'s series is the user's choice (made here, or remembered in the settings).
    void markChosen(int id);
    /// The largest gear ratio offered (EncoderView's bound).
    static constexpr double kMaxGearRatio = 1000;

signals:
    void seriesChosen(int id, lk::protocol::Series series);
    /// The user set the gear ratio of drive `id` (1 : ratio), for a drive without a model name.
    void gearRatioChosen(int id, double ratio);
    /// The user chose the CAN generation of drive `id` (V2_3: old CAN, V2_35: V2.36).
    void generationChosen(int id, lk::protocol::Generation generation);

private:
    void refresh();
    void onActivated(int index);
    void onRatioEdited();
    void onGenerationActivated(int index);

    BusModel *m_model;
    QLabel *m_label;
    QComboBox *m_combo;
    QLabel *m_ratioLabel;
    QDoubleSpinBox *m_ratio;
    QLabel *m_generationLabel;
    QComboBox *m_generation; ///< CAN only: unknown, old CAN, CAN V2.36
    QSet<int> m_chosen;      ///< drives whose series the user chose (on this bus)
};

} // namespace lk::ui
