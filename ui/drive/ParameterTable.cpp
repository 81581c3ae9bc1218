#include "ParameterTable.h"

#include <panels/StatusColors.h>

#include <QtCore/QEvent>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QGridLayout>
#include <QtWidgets/QLabel>
#include <QtWidgets/QStyle>

#include <cmath>

namespace lk::ui {

namespace {
const char kChangedProperty[] = "changed";

QString dash()
{
    return QStringLiteral("\u2013");
}

double scaleOf(const ParamField &f)
{
    return std::pow(10.0, f.decimals);
}

// An edit field's value while the pending edit is unknown: one step below every real value,
// shown as the special value text.
double unknownOf(const ParamField &f)
{
    return double(f.min - 1) / scaleOf(f);
}
} // namespace

ParameterTable::ParameterTable(QWidget *parent) : QWidget(parent)
{
    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setHorizontalSpacing(12);
    const QString headers[] = {tr("Parameter"), tr("First read"), tr("Drive holds"),
                               tr("Pending edit")};
    for (int c = 0; c < 4; ++c) {
        auto *h = new QLabel(QStringLiteral("<b>%1</b>").arg(headers[c].toHtmlEscaped()), this);
        grid->addWidget(h, 0, c);
    }
    grid->setColumnStretch(4, 1);
    applyChangedStyle();
}

void ParameterTable::setFields(const QVector<ParamField> &fields)
{
    qDeleteAll(m_rowWidgets);
    m_rowWidgets.clear();
    m_rows.clear();
    m_pendingKnown = false;
    m_rows.reserve(fields.size());
    for (int r = 0; r < fields.size(); ++r)
        buildRow(fields.at(r), r + 1);
}

void ParameterTable::buildRow(const ParamField &field, int gridRow)
{
    auto *grid = static_cast<QGridLayout *>(layout());
    RowWidgets w;
    w.field = field;
    w.name = new QLabel(field.name, this);
    w.original = new QLabel(dash(), this);
    w.holds = new QLabel(tr("unknown"), this);
    w.edit = new QDoubleSpinBox(this);
    w.edit->setObjectName(QStringLiteral("pending_") + field.key);
    w.holds->setObjectName(QStringLiteral("holds_") + field.key);
    w.original->setObjectName(QStringLiteral("first_") + field.key);
    w.original->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    w.holds->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    w.edit->setDecimals(field.decimals);
    w.edit->setRange(unknownOf(field), double(field.max) / scaleOf(field));
    w.edit->setValue(unknownOf(field));
    w.edit->setSpecialValueText(tr("unknown"));
    w.edit->setEnabled(false);
    w.edit->setSuffix(field.suffix);
    w.edit->setSingleStep(field.step);
    w.edit->setToolTip(field.tip);
    w.edit->setKeyboardTracking(false);
    w.edit->installEventFilter(this);
    connect(w.edit, &QDoubleSpinBox::valueChanged, this, [this] {
        refreshHighlight();
        emit edited();
    });
    grid->addWidget(w.name, gridRow, 0);
    grid->addWidget(w.original, gridRow, 1);
    grid->addWidget(w.holds, gridRow, 2);
    grid->addWidget(w.edit, gridRow, 3);
    m_rowWidgets << w.name << w.original << w.holds << w.edit;
    m_rows << w;
}

qint64 ParameterTable::wireValue(int row) const
{
    const RowWidgets &w = m_rows.at(row);
    return qRound64(w.edit->value() * scaleOf(w.field));
}

void ParameterTable::setHolds(const HeldValues &held)
{
    for (int r = 0; r < rowCount(); ++r) {
        const std::optional<qint64> v = held.value(r);
        m_rows[r].holdsValue = v;
        m_rows[r].holds->setText(v ? ParamSetSpec::shown(m_rows[r].field, *v).trimmed()
                                   : tr("unknown"));
    }
    refreshHighlight();
}

void ParameterTable::setOriginal(const std::optional<ParamValues> &values)
{
    for (int r = 0; r < rowCount(); ++r) {
        m_rows[r].original->setText(
            values && r < values->size()
                ? ParamSetSpec::shown(m_rows[r].field, values->at(r)).trimmed()
                : dash());
    }
}

void ParameterTable::setPending(const ParamValues &values)
{
    m_pendingKnown = true;
    for (int r = 0; r < rowCount(); ++r) {
        RowWidgets &w = m_rows[r];
        QSignalBlocker block(w.edit);
        // A known value at the field's minimum (a limit of 0) is that value, not "unknown":
        // the special text shows at the minimum, so it goes while the values are known.
        w.edit->setSpecialValueText(QString());
        w.edit->setMinimum(double(w.field.min) / scaleOf(w.field));
        w.edit->setValue(double(values.value(r)) / scaleOf(w.field));
    }
    refreshHighlight();
}

void ParameterTable::clearPending()
{
    m_pendingKnown = false;
    for (RowWidgets &w : m_rows) {
        QSignalBlocker block(w.edit);
        w.edit->setSpecialValueText(tr("unknown"));
        w.edit->setMinimum(unknownOf(w.field));
        w.edit->setValue(unknownOf(w.field));
    }
    setEditable(false);
    refreshHighlight();
}

void ParameterTable::setEditable(bool editable)
{
    for (const RowWidgets &w : std::as_const(m_rows))
        w.edit->setEnabled(editable && m_pendingKnown);
}

std::optional<ParamValues> ParameterTable::pending() const
{
    if (!m_pendingKnown)
        return std::nullopt;
    ParamValues values;
    for (int r = 0; r < rowCount(); ++r)
        values << wireValue(r);
    return values;
}

bool ParameterTable::isChanged(int row) const
{
    const RowWidgets &w = m_rows.at(row);
    return m_pendingKnown && (!w.holdsValue || *w.holdsValue != wireValue(row));
}

bool ParameterTable::anyChanged() const
{
    for (int r = 0; r < rowCount(); ++r) {
        if (isChanged(r))
            return true;
    }
    return false;
}

void ParameterTable::refreshHighlight()
{
    for (int r = 0; r < rowCount(); ++r) {
        RowWidgets &w = m_rows[r];
        const bool changed = isChanged(r);
        if (w.edit->property(kChangedProperty).toBool() == changed)
            continue;
        w.edit->setProperty(kChangedProperty, changed);
        w.edit->style()->unpolish(w.edit);
        w.edit->style()->polish(w.edit);
        QFont f = w.name->font();
        f.setBold(changed);
        w.name->setFont(f);
    }
}

void ParameterTable::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        applyChangedStyle();
}

void ParameterTable::applyChangedStyle()
{
    const QString sheet =
        QStringLiteral("QDoubleSpinBox[changed=\"true\"] { background: %1; }")
            .arg(StatusColors::background(StatusColors::Role::Warning, palette()).name());
    if (sheet != styleSheet()) // a style sheet change must not loop through PaletteChange
        setStyleSheet(sheet);
}

bool ParameterTable::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::FocusIn) {
        for (const RowWidgets &w : std::as_const(m_rows)) {
            if (w.edit == watched)
                emit loopFocused(w.field.loop);
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace lk::ui
