#pragma once

#include <protocol/Series.h>

#include <QtCore/QSet>
#include <QtWidgets/QWidget>

class QComboBox;
class QLabel;

namespace lk::ui {

class BusModel;

/// The series of the current drive, chosen by the user where the bus could not learn it (no
/// 0x12 model reply seen, typically a drive only listened to): MS, MF, MG or MH. Shown while
/// the current drive's series is unknown or was chosen here; until then an MS drive's power
/// is not shown as current anywhere.
class SeriesChooser : public QWidget {
    Q_OBJECT
public:
    explicit SeriesChooser(BusModel *model, QWidget *parent = nullptr);

    /// Drive `id`'s series is the user's choice (made here, or remembered in the settings).
    void markChosen(int id);

signals:
    void seriesChosen(int id, lk::protocol::Series series);

private:
    void refresh();
    void onActivated(int index);

    BusModel *m_model;
    QLabel *m_label;
    QComboBox *m_combo;
    QSet<int> m_chosen; ///< drives whose series the user chose (on this bus)
};

} // namespace lk::ui
