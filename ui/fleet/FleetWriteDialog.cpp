#include "FleetWriteDialog.h"

#include <drive/ConfirmDialog.h>
#include <fleet/BackupFile.h>
#include <fleet/FleetCatalog.h>

#include <QtWidgets/QDialogButtonBox>
#include <QtWidgets/QLabel>
#include <QtWidgets/QPlainTextEdit>
#include <QtWidgets/QPushButton>
#include <QtWidgets/QVBoxLayout>

namespace lk::ui {

using fleet::DriveReport;

FleetWriteDialog::FleetWriteDialog(bus::BusSession *session,
                                   const QVector<fleet::FleetRestore::Job> &jobs,
                                   const QString &title, const QString &undoPath, QWidget *parent)
    : QDialog(parent), m_restore(session), m_undoPath(undoPath)
{
    setObjectName(QStringLiteral("fleetWriteDialog"));
    setWindowTitle(title);
    auto *layout = new QVBoxLayout(this);
    m_state = new QLabel(tr("Reading the target drives before anything is written..."), this);
    m_state->setObjectName(QStringLiteral("state"));
    m_state->setWordWrap(true);
    m_text = new QPlainTextEdit(this);
    m_text->setObjectName(QStringLiteral("diff"));
    m_text->setReadOnly(true);
    m_text->setMinimumSize(520, 280);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_ram = buttons->addButton(tr("Write to RAM"), QDialogButtonBox::ActionRole);
    m_ram->setObjectName(QStringLiteral("writeRam"));
    m_ram->setToolTip(tr("Writes the values that change, then reads every target back. Lost at "
                         "power-off."));
    m_rom = buttons->addButton(tr("Write to ROM..."), QDialogButtonBox::ActionRole);
    m_rom->setObjectName(QStringLiteral("writeRom"));
    m_rom->setToolTip(tr("RAM first and read back; then, for each drive that matched, the ROM "
                         "frames once each (asks first)."));
    for (QPushButton *b : {m_ram, m_rom})
        b->setEnabled(false);
    buttons->button(QDialogButtonBox::Close)->setAutoDefault(true);
    layout->addWidget(m_state);
    layout->addWidget(m_text, 1);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_ram, &QPushButton::clicked, this, [this] { write(false); });
    connect(m_rom, &QPushButton::clicked, this, [this] { write(true); });
    connect(&m_restore, &fleet::FleetRestore::prepared, this, &FleetWriteDialog::onPrepared);
    connect(&m_restore, &fleet::FleetRestore::finished, this, &FleetWriteDialog::onFinished);
    connect(&m_restore, &fleet::FleetRestore::progress, this, [this](int done, int total) {
        m_state->setText(tr("Drive %1 of %2 ...").arg(done).arg(total));
    });
    m_restore.prepare(jobs);
}

QString FleetWriteDialog::text() const
{
    return m_state->text() + QLatin1Char('\n') + m_text->toPlainText();
}

QString FleetWriteDialog::planText(const fleet::RestorePlan &plan) const
{
    const QString head = tr("Drive %1 from drive %2: ").arg(plan.targetId()).arg(plan.source.id());
    if (plan.refusal)
        return head + tr("refused, nothing will be sent to it (%1): %2")
                          .arg(plan.refusal->key, plan.refusal->reason);
    if (plan.changes.isEmpty())
        return head + tr("already holds every value");
    QString text = head + tr("%n value(s) change", nullptr, int(plan.changes.size()));
    if (!hasRom(plan))
        text += tr(" (RAM only: CAN V2.36 has no ROM for these parameters; Write to RAM writes "
                   "it, Write to ROM refuses it and sends it nothing)");
    for (const fleet::ParamChange &c : plan.changes)
        text += QStringLiteral("\n    %1: %2 -> %3").arg(c.key).arg(c.from).arg(c.to);
    return text;
}

void FleetWriteDialog::onPrepared()
{
    m_prepared = true;
    fleet::BackupFile undo;
    undo.savedAt = QDateTime::currentDateTimeUtc();
    undo.drives = m_restore.undo();
    const QString why = undo.save(m_undoPath);
    QStringList lines;
    bool any = false;
    bool anyRom = false;
    for (const fleet::RestorePlan &p : m_restore.plans()) {
        lines << planText(p);
        any |= !p.refusal;
        anyRom |= !p.refusal && hasRom(p);
    }
    m_text->setPlainText(lines.join(QLatin1Char('\n')));
    if (!why.isEmpty()) {
        m_state->setText(tr("The targets' values could not be saved (%1): nothing will be "
                            "written.")
                             .arg(why));
        return;
    }
    m_state->setText(tr("Targets read; their values are saved in %1 (a backup: restoring it "
                        "undoes this). Nothing has been written yet.")
                         .arg(m_undoPath));
    m_ram->setEnabled(any);
    // A CAN V2.36 drive keeps these parameters in RAM only (0xC1): with no other target, there
    // is nothing a ROM write could do (FleetRestore would refuse it too).
    m_rom->setEnabled(anyRom);
    if (any && !anyRom)
        m_rom->setToolTip(tr("The targets are CAN V2.36 drives: their control parameters are "
                             "RAM only (0xC1), there is no ROM write. Write to RAM instead."));
}

bool FleetWriteDialog::hasRom(const fleet::RestorePlan &plan)
{
    const fleet::DriveIdentity &to = plan.target.identity;
    return fleet::FleetCatalog::hasRom(to.generation, to.link);
}

void FleetWriteDialog::write(bool rom)
{
    if (rom) {
        ConfirmRequest q;
        q.key = QStringLiteral("fleet_rom");
        q.title = tr("Write to ROM");
        q.question = tr("Write these values to the ROM of every drive that is not refused?");
        q.reason = tr("ROM is the drives' flash: each write wears it, and the values stay after "
                      "power-off. RAM is written and read back first; ROM only where it "
                      "matched, each frame once, never repeated. V2.3 drives cannot read ROM "
                      "back: the report says what was not verified.");
        q.acceptText = tr("Write to ROM");
        if (!ConfirmDialog::ask(this, q)) {
            m_state->setText(tr("Cancelled: nothing was sent."));
            return;
        }
    }
    m_ram->setEnabled(false);
    m_rom->setEnabled(false);
    m_state->setText(tr("Writing ..."));
    m_restore.execute(rom);
}

QString FleetWriteDialog::reportText(const DriveReport &r) const
{
    QString outcome;
    switch (r.outcome) {
    case DriveReport::Outcome::Verified:
        outcome = tr("verified: written and read back equal");
        break;
    case DriveReport::Outcome::Written:
        outcome = tr("written, not all of it verifiable");
        break;
    case DriveReport::Outcome::Unchanged:
        outcome = tr("unchanged: it already held every value, nothing was sent");
        break;
    case DriveReport::Outcome::Differs:
        outcome = tr("differs: the read-back is not what was written");
        break;
    case DriveReport::Outcome::Refused:
        outcome = tr("refused: nothing was sent");
        break;
    case DriveReport::Outcome::Failed:
        outcome = tr("failed");
        break;
    }
    QStringList notes = r.mismatches + r.notVerified;
    if (!r.reason.isEmpty())
        notes.prepend(r.reason);
    return tr("Drive %1: %2").arg(r.targetId).arg(outcome) +
           (notes.isEmpty() ? QString()
                            : QStringLiteral("\n    ") + notes.join(QStringLiteral("\n    ")));
}

void FleetWriteDialog::onFinished()
{
    m_finished = true;
    QStringList lines;
    for (const DriveReport &r : m_restore.reports())
        lines << reportText(r);
    m_text->appendPlainText(QStringLiteral("\n") + lines.join(QLatin1Char('\n')));
    m_state->setText(tr("Done. The values before are in %1.").arg(m_undoPath));
}

} // namespace lk::ui
