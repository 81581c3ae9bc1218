#include "EnglishTextFinder.h"

#include <protocol/Command.h>

#include <QtCharts/QAbstractAxis>
#include <QtCharts/QAbstractSeries>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCore/QAbstractItemModel>
#include <QtCore/QRegularExpression>
#include <QtGui/QAction>
#include <QtGui/QTextDocumentFragment>
#include <QtWidgets/QAbstractButton>
#include <QtWidgets/QAbstractItemView>
#include <QtWidgets/QComboBox>
#include <QtWidgets/QDockWidget>
#include <QtWidgets/QDoubleSpinBox>
#include <QtWidgets/QGroupBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QLineEdit>
#include <QtWidgets/QMenu>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QSpinBox>
#include <QtWidgets/QTabBar>
#include <QtWidgets/QTextEdit>
#include <QtWidgets/QToolBar>

namespace {
// Units, acronyms, protocol and product names: the same in every language ("English" is the
// language menu naming English in English).
// CAN: the Qt SerialBus plugin names (listed as Qt reports them) and the commands to run.
const char *const kAllowed[] = {
    "dps",
    "rpm",
    "Hz",
    "ms",
    "RAM",
    "ROM",
    "PID",
    "ID",
    "IDs",
    "CSV",
    "JSON",
    "PNG",
    "HTML",
    "INI",
    "Kp",
    "Ki",
    "iq",
    "MS",
    "MF",
    "MG",
    "MH",
    "LK",
    "TECH",
    "RS",
    "USB",
    "lkstudio",
    "lkctl",
    "lksim",
    "Esc",
    "Ctrl",
    "Servo",
    "Studio",
    "UTC",
    "sudo",
    "usermod",
    "aG",
    "USER",
    "dialout",
    "uucp",
    "Debian",
    "Ubuntu",
    "Arch",
    "fuser",
    "ModemManager",
    "ERRATA",
    "FOC",
    "dev",
    "tty",
    "pts",
    "ttyUSB",
    "ttyS",
    "COM",
    "decode",
    "DRV",
    "English",
    "txt",
    "json",
    "csv",
    "png",
    "min",
    "max",
    "Alt",
    "Shift",
    "FTDI",
    "RTS",
    "DTR",
    "README",
    "CAN",
    "PCAN",
    "CANable",
    "dB",
    "SerialBus",
    "socketcan",
    "peakcan",
    "passthrucan",
    "tinycan",
    "virtualcan",
    "vcan",
    "slcand",
    "Linux",
    "ip",
    "link",
    "show",
    "root",
    // candump and can-utils, python-can and SavvyCAN: the CAN log format and the programs that
    // read it, names that stay as they are.
    "candump",
    "can",
    "utils",
    "python",
    "SavvyCAN",
};
const QRegularExpression kWord(QStringLiteral("(?<![A-Za-z0-9_./])[A-Za-z]{2,}(?![A-Za-z0-9_/])"));
} // namespace

EnglishTextFinder::EnglishTextFinder()
{
    for (const char *w : kAllowed)
        m_allowed.insert(QLatin1String(w));
    m_allowed.insert(QStringLiteral("Qt")); // a product name: Help > About Qt
    // Command names with an underscore ("motor_off") are identifiers shared with lkctl; the
    // one-word ones ("torque", "speed") are also plain English words, so they are not allowed
    // here (the traffic view's Command column is skipped as protocol data instead).
    for (const auto &info : lk::protocol::CommandTable::all()) {
        if (QLatin1String(info.name).contains(QLatin1Char('_')))
            m_allowed.insert(QLatin1String(info.name));
    }
}

QStringList EnglishTextFinder::englishWords(const QString &text) const
{
    QString plain =
        Qt::mightBeRichText(text) ? QTextDocumentFragment::fromHtml(text).toPlainText() : text;
    plain.remove(QLatin1Char('&')); // accelerators: "&File" is the word "File"
    QStringList words;
    auto it = kWord.globalMatch(plain);
    while (it.hasNext()) {
        const QString w = it.next().captured();
        if (!m_allowed.contains(w))
            words << w;
    }
    return words;
}

void EnglishTextFinder::check(const QString &where, const QString &text)
{
    if (!text.trimmed().isEmpty())
        ++m_checked;
    const QStringList words = englishWords(text);
    if (words.isEmpty())
        return;
    const QString line = QStringLiteral("%1: \"%2\" [%3]")
                             .arg(where, text.left(120), words.join(QStringLiteral(", ")));
    if (!m_findings.contains(line))
        m_findings << line;
}

void EnglishTextFinder::walk(QWidget *root)
{
    checkWidget(root);
    const auto children = root->findChildren<QWidget *>();
    for (QWidget *w : children)
        checkWidget(w);
}

void EnglishTextFinder::checkWidget(QWidget *w)
{
    const QString where = QStringLiteral("%1 \"%2\"")
                              .arg(QLatin1String(w->metaObject()->className()), w->objectName());
    check(where + QStringLiteral(" tooltip"), w->toolTip());
    check(where + QStringLiteral(" status tip"), w->statusTip());
    if (w->isWindow() || qobject_cast<QDockWidget *>(w) || qobject_cast<QToolBar *>(w))
        check(where + QStringLiteral(" title"), w->windowTitle());
    for (QAction *a : w->actions()) {
        check(where + QStringLiteral(" action"), a->text());
        check(where + QStringLiteral(" action tooltip"), a->toolTip());
        if (a->menu())
            checkMenu(where, a->menu());
    }
    if (auto *l = qobject_cast<QLabel *>(w))
        check(where, l->text());
    if (auto *b = qobject_cast<QAbstractButton *>(w))
        check(where, b->text());
    if (auto *g = qobject_cast<QGroupBox *>(w))
        check(where, g->title());
    if (auto *e = qobject_cast<QLineEdit *>(w))
        check(where + QStringLiteral(" placeholder"), e->placeholderText());
    if (auto *e = qobject_cast<QTextEdit *>(w))
        check(where, e->toPlainText());
    if (auto *e = qobject_cast<QPlainTextEdit *>(w))
        check(where, e->toPlainText() + QLatin1Char(' ') + e->placeholderText());
    if (auto *c = qobject_cast<QComboBox *>(w); c && !m_identifierLists.contains(w->objectName())) {
        for (int i = 0; i < c->count(); ++i)
            check(where + QStringLiteral(" item"), c->itemText(i));
    }
    if (auto *s = qobject_cast<QSpinBox *>(w))
        check(where, s->prefix() + QLatin1Char(' ') + s->suffix() + QLatin1Char(' ') +
                         s->specialValueText());
    if (auto *s = qobject_cast<QDoubleSpinBox *>(w))
        check(where, s->prefix() + QLatin1Char(' ') + s->suffix() + QLatin1Char(' ') +
                         s->specialValueText());
    if (auto *t = qobject_cast<QTabBar *>(w)) {
        for (int i = 0; i < t->count(); ++i)
            check(where + QStringLiteral(" tab"),
                  t->tabText(i) + QLatin1Char(' ') + t->tabToolTip(i));
    }
    if (auto *v = qobject_cast<QAbstractItemView *>(w))
        checkModel(where, v->model());
    checkChart(where, w);
}

void EnglishTextFinder::checkMenu(const QString &where, QMenu *menu)
{
    check(where + QStringLiteral(" menu"), menu->title());
    for (QAction *a : menu->actions()) {
        check(where + QStringLiteral(" menu item"), a->text());
        if (a->menu() && a->menu() != menu)
            checkMenu(where, a->menu());
    }
}

void EnglishTextFinder::checkModel(const QString &where, const QAbstractItemModel *model)
{
    if (!model)
        return;
    constexpr int kMaxRows = 40; // every kind of row, not every row of a long log
    for (int c = 0; c < model->columnCount(); ++c) {
        check(where + QStringLiteral(" header"), model->headerData(c, Qt::Horizontal).toString());
        check(where + QStringLiteral(" header tooltip"),
              model->headerData(c, Qt::Horizontal, Qt::ToolTipRole).toString());
    }
    const int rows = qMin(model->rowCount(), kMaxRows);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < model->columnCount(); ++c) {
            if (m_ignoredColumns.contains(model->headerData(c, Qt::Horizontal).toString()))
                continue;
            const QModelIndex i = model->index(r, c);
            check(where + QStringLiteral(" cell"), i.data(Qt::DisplayRole).toString());
            check(where + QStringLiteral(" cell tooltip"), i.data(Qt::ToolTipRole).toString());
            // Tree rows (the drive list): one level of children.
            for (int k = 0; k < qMin(model->rowCount(i), kMaxRows); ++k)
                check(where + QStringLiteral(" child"),
                      model->index(k, c, i).data(Qt::DisplayRole).toString());
        }
    }
}

void EnglishTextFinder::checkChart(const QString &where, QWidget *w)
{
    auto *view = qobject_cast<QChartView *>(w);
    if (!view || !view->chart())
        return;
    QChart *chart = view->chart();
    check(where + QStringLiteral(" chart title"), chart->title());
    for (QAbstractAxis *axis : chart->axes())
        check(where + QStringLiteral(" axis"), axis->titleText());
    for (QAbstractSeries *s : chart->series())
        check(where + QStringLiteral(" series"), s->name());
}
