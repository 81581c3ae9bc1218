// The generator's waveforms: their value at a time since the start, for each shape.

#include <bus/SetpointWaveform.h>

#include <QtTest/QtTest>

#include <cmath>

using lk::bus::SetpointWaveform;

class tst_SetpointWaveform : public QObject {
    Q_OBJECT
private slots:
    void generatorWaveforms_data();
    void generatorWaveforms();
};

void tst_SetpointWaveform::generatorWaveforms_data()
{
    QTest::addColumn<int>("waveform");
    QTest::addColumn<double>("t");
    QTest::addColumn<double>("expected");
    using W = SetpointWaveform::Waveform;
    // amplitude 10, offset 5, period 2 s
    QTest::newRow("step before") << int(W::Step) << 0.5 << 5.0;
    QTest::newRow("step after") << int(W::Step) << 1.5 << 15.0;
    QTest::newRow("step stays") << int(W::Step) << 9.0 << 15.0;
    QTest::newRow("square high") << int(W::Square) << 0.2 << 15.0;
    QTest::newRow("square low") << int(W::Square) << 1.2 << -5.0;
    QTest::newRow("sine 0") << int(W::Sine) << 0.0 << 5.0;
    QTest::newRow("sine peak") << int(W::Sine) << 0.5 << 15.0;
    QTest::newRow("sine trough") << int(W::Sine) << 1.5 << -5.0;
    QTest::newRow("ramp 0") << int(W::Ramp) << 0.0 << 5.0;
    QTest::newRow("ramp up") << int(W::Ramp) << 0.25 << 10.0;
    QTest::newRow("ramp top") << int(W::Ramp) << 0.5 << 15.0;
    QTest::newRow("ramp bottom") << int(W::Ramp) << 1.5 << -5.0;
    QTest::newRow("ramp next cycle") << int(W::Ramp) << 2.5 << 15.0;
}

void tst_SetpointWaveform::generatorWaveforms()
{
    QFETCH(int, waveform);
    QFETCH(double, t);
    QFETCH(double, expected);
    SetpointWaveform::Settings s;
    s.waveform = SetpointWaveform::Waveform(waveform);
    s.amplitude = 10;
    s.offset = 5;
    s.periodS = 2;
    QVERIFY(std::fabs(SetpointWaveform::valueAt(s, t) - expected) < 1e-9);
}

QTEST_APPLESS_MAIN(tst_SetpointWaveform)
#include "tst_setpointwaveform.moc"
