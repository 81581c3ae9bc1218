#pragma once

#include "ParamSetSpec.h"

#include <QtCore/QVector>
#include <QtWidgets/QWidget>

#include <optional>

class QLabel;
class QDoubleSpinBox;

namespace lk::ui {

/// The values of one drive's parameter set side by side: what it held at the first read, what
/// it holds now (last read back), and the pending edit. The rows come from a ParamSetSpec's
/// fields. A value not read shows as "unknown", never as 0: the pending edit is unknown until
/// set from a read or a file. Pending values that differ from the drive (or whose drive value
/// is unknown) are highlighted.
class ParameterTable : public QWidget {
    Q_OBJECT
public:
    explicit ParameterTable(QWidget *parent = nullptr);

    /// Rebuilds the rows for `fields`; everything shows unknown.
    void setFields(const QVector<ParamField> &fields);
    int rowCount() const { return int(m_rows.size()); }
    const ParamField &field(int row) const { return m_rows.at(row).field; }

    void setHolds(const HeldValues &held);
    /// The "first read" column; nullopt shows a dash (nothing read yet).
    void setOriginal(const std::optional<ParamValues> &values);
    /// Sets the edit fields (does not emit edited()).
    void setPending(const ParamValues &values);
    /// Every edit field back to "unknown" (nothing to write until set again).
    void clearPending();
    void setEditable(bool editable);

    /// The pending edit (wire values), or nullopt while it is unknown.
    std::optional<ParamValues> pending() const;
    /// The pending value differs from what the drive holds (or the drive's value is unknown);
    /// false while the pending edit is unknown.
    bool isChanged(int row) const;
    bool anyChanged() const;
    QDoubleSpinBox *editor(int row) const { return m_rows.at(row).edit; }

signals:
    /// The user changed a pending value.
    void edited();
    /// An edit field of this loop took the keyboard focus.
    void loopFocused(lk::ui::TunedLoop loop);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    struct RowWidgets {
        ParamField field;
        QLabel *name = nullptr;
        QLabel *original = nullptr;
        QLabel *holds = nullptr;
        QDoubleSpinBox *edit = nullptr;
        std::optional<qint64> holdsValue;
    };
    void buildRow(const ParamField &field, int gridRow);
    qint64 wireValue(int row) const;
    void refreshHighlight();
    /// The "pending edit" tint, light or dark after the palette.
    void applyChangedStyle();

    QVector<RowWidgets> m_rows;
    QList<QWidget *> m_rowWidgets;
    bool m_pendingKnown = false;
};

} // namespace lk::ui
