#pragma once

#include "ConfirmDialog.h"

#include <protocol/Reply.h>
#include <protocol/Request.h>
#include <protocol/Series.h>
#include <record/ParameterSet.h>

#include <QtCore/QCoreApplication>
#include <QtCore/QString>
#include <QtCore/QStringList>
#include <QtCore/QVector>

#include <optional>

namespace lk::ui {

/// The loop a tuning parameter belongs to (decides what the live plot shows).
enum class TunedLoop { Angle, Speed, Current };

/// One value a parameter editor shows: an integer on the wire, shown as wire / 10^decimals.
struct ParamField {
    QString key;  ///< "angle_kp", "max_speed_dps" (CLI.md names; object names of the widgets)
    QString name; ///< translated row label
    TunedLoop loop = TunedLoop::Speed;
    qint64 min = 0; ///< wire range
    qint64 max = 0;
    int decimals = 0; ///< 2 for a value carried in 0.01 units
    QString suffix;   ///< " dps", shown after the number
    QString tip;
    int step = 1; ///< spin box step, in shown units
};

/// Wire values, one per field of a ParamSetSpec, all known.
using ParamValues = QVector<qint64>;
/// What a drive holds, one per field; nullopt while not read.
using HeldValues = QVector<std::optional<qint64>>;

/// One frame of a write, with the fields it carries (named when it fails).
struct ParamWrite {
    protocol::BuildResult built;
    QVector<int> fields;
};

/// What a write sent, to compare with the read-back that follows it.
struct SentValues {
    bool rom = false;
    ParamValues values;
    QVector<int> fields; ///< the fields the write carried
};

/// How a view presents a set: its group title, a note under the table, and button tool tips.
struct ParamSetTexts {
    QString title;
    QString note;
    QString readTip;
    QString ramTip;
    QString romTip;
};

/// A set of drive parameters as one protocol generation reads and writes them: the rows of a
/// parameter table, the requests of a complete read, the frames of a write, and the words for
/// what a write does and what its read-back proved. The tuning view and the drive limits view
/// run the same read / write / read-back cycle on any set.
class ParamSetSpec {
    Q_DECLARE_TR_FUNCTIONS(lk::ui::ParamSetSpec)
public:
    virtual ~ParamSetSpec() = default;

    virtual protocol::Generation generation() const = 0;
    /// The set lives in RAM only (CAN V2.36): nothing of it is ever written to ROM.
    virtual bool ramOnly() const { return false; }
    virtual QVector<ParamField> fields() const = 0;
    virtual ParamSetTexts texts() const = 0;
    /// The requests of one complete read of drive `id`.
    virtual QVector<protocol::Request> reads(int id) const = 0;
    /// What the replies of reads() say the drive holds (fields without a reply stay unknown).
    virtual HeldValues decode(const QVector<protocol::Reply> &replies) const = 0;
    /// The frames that write `values` to RAM or ROM. `held` is what the drive holds (all known).
    virtual QVector<ParamWrite> writes(int id, const ParamValues &values, const ParamValues &held,
                                       bool rom) const = 0;
    /// "Angle Kp 100, Ki 100, Kd 0; ..." for questions and warnings.
    virtual QString valuesText(const ParamValues &values) const;
    /// The question before a ROM write (says why it is asked).
    virtual ConfirmRequest romQuestion(int id, const ParamValues &values) const = 0;
    /// Where the read-back differs from what was sent; empty when the drive holds what was sent.
    virtual QStringList readBackProblems(const SentValues &sent, const HeldValues &held) const;
    /// The status after a write whose read-back showed what was sent.
    virtual QString written(const SentValues &sent, int id) const = 0;

    /// Puts the gains of `held` into a parameter file; false when too little is known.
    virtual bool toFile(const HeldValues &held, record::ParameterSet &set) const;
    /// The pending edit a parameter file of this generation gives (values the file does not
    /// hold are taken from `current`); nullopt when the set cannot be loaded into files.
    virtual std::optional<ParamValues> fromFile(const record::ParameterSet &set,
                                                const ParamValues &current) const;
    /// "Angle loop Kp 100, Angle loop Ki 40" for the fields given.
    QString fieldsText(const ParamValues &values, const QVector<int> &fields) const;

    /// A field's wire value as shown: "12.50 dps".
    static QString shown(const ParamField &field, qint64 value);
    /// All values known: the values; otherwise nullopt.
    static std::optional<ParamValues> known(const HeldValues &held);
};

} // namespace lk::ui
