#include <drive/EncoderLiveBox.h>

#include <QtTest/QtTest>
#include <QtWidgets/QLabel>

using lk::motor::EncoderResolution;
using lk::motor::ModelNameInfo;
using lk::protocol::EncoderReading;
using lk::protocol::Series;
using lk::ui::EncoderLiveBox;

namespace {
EncoderResolution assumed14()
{
    // The MS series' 12 bits raised by a value of 6437: a resolution only assumed.
    EncoderResolution r = EncoderResolution::fromModel(ModelNameInfo::parse("MS4015"), Series::MS);
    r.observe(6437);
    return r;
}

QString text(EncoderLiveBox &box, const char *name)
{
    return box.findChild<QLabel *>(QLatin1String(name))->text();
}
} // namespace

/// The Encoder view's live readouts never show two angles of one shaft that disagree.
class tst_EncoderLiveBox : public QObject {
    Q_OBJECT
private slots:
    void disagreeingAngleIsNotShown();
    void agreeingAnglesAreBothShown();
    void knownResolutionShowsBoth();
};

void tst_EncoderLiveBox::disagreeingAngleIsNotShown()
{
    // The issue: "6437 of 16384 (14-bit, from data) (141.44 deg)" beside "single-turn 35.36".
    EncoderLiveBox box;
    const EncoderReading e{6437, 6437, 0};
    QVERIFY(EncoderLiveBox::anglesDisagree(e, 35.36, assumed14(), 1.0));
    box.setValues(e, 35.36, 35.36, assumed14(), 1.0);
    const QString encoder = text(box, "encoderValue");
    QVERIFY2(!encoder.contains(QStringLiteral("141.44")) && encoder.contains("no angle"),
             qPrintable(encoder));
    QVERIFY(!text(box, "encoderRaw").contains(QStringLiteral("\u00b0")));
    QCOMPARE(text(box, "singleTurn"), QStringLiteral("35.36\u00b0"));
}

void tst_EncoderLiveBox::agreeingAnglesAreBothShown()
{
    EncoderLiveBox box;
    const EncoderReading e{6437, 6437, 0};
    // 6437 of 16384 is 141.44 deg: where the single-turn angle says so, both are shown.
    QVERIFY(!EncoderLiveBox::anglesDisagree(e, 141.0, assumed14(), 1.0));
    box.setValues(e, 141.0, 141.0, assumed14(), 1.0);
    QVERIFY(text(box, "encoderValue").contains(QStringLiteral("(141.44\u00b0)")));
    // A gearbox: the single-turn angle is not the rotor's, nothing to compare.
    QVERIFY(!EncoderLiveBox::anglesDisagree(e, 35.36, assumed14(), 10.0));
    // Nothing read yet: nothing disagrees.
    QVERIFY(!EncoderLiveBox::anglesDisagree(std::nullopt, 35.36, assumed14(), 1.0));
    QVERIFY(!EncoderLiveBox::anglesDisagree(e, std::nullopt, assumed14(), 1.0));
}

void tst_EncoderLiveBox::knownResolutionShowsBoth()
{
    // With the resolution known (here from protocol V2.35), a difference is a zero moved since
    // (clear angle, 0x95), not a wrong resolution: both are shown.
    const EncoderResolution v235 = EncoderResolution::fromModel(
        ModelNameInfo::parse("MS4015"), Series::MS, lk::protocol::Generation::V2_35);
    const EncoderReading e{6437, 6437, 0};
    QVERIFY(!EncoderLiveBox::anglesDisagree(e, 100.0, v235, 1.0));
    EncoderLiveBox box;
    box.setValues(e, 35.36, 35.36, v235, 1.0);
    QVERIFY(text(box, "encoderValue").contains(QStringLiteral("(35.36\u00b0)")));
}

QTEST_MAIN(tst_EncoderLiveBox)
#include "tst_encoderlivebox.moc"
