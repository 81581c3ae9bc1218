#pragma once

// Shared by the plot panel's tests: telemetry to feed a TelemetryStore, and a shown panel.

#include <bus/TelemetrySample.h>
#include <plot/PlotPanel.h>
#include <plot/TelemetryStore.h>

#include <QtTest/QTest>

#include <cmath>

namespace lk::plottest {

/// One sample of an MF-like drive carrying iq, speed, encoder and multi-turn angle.
inline bus::TelemetrySample sample(int id, double t, double iq, double speed, int encoder)
{
    bus::TelemetrySample s;
    s.id = id;
    s.time = t;
    s.fields = bus::TelemetryField::IqA | bus::TelemetryField::Speed |
               bus::TelemetryField::Encoder | bus::TelemetryField::MultiTurn;
    s.iqA = iq;
    s.speedDps = speed;
    s.encoder = encoder;
    s.multiTurnDeg = speed * 2;
    return s;
}

// `count` samples of drive `id` from `t0` every `dt` seconds: a sine with a ramp.
inline bus::TelemetryBatch batch(int id, double t0, int count, double dt)
{
    bus::TelemetryBatch b;
    for (int i = 0; i < count; ++i) {
        const double t = t0 + i * dt;
        b.append(sample(id, t, std::sin(t * 7), 100 * std::sin(t), int(t * 100) % 16384));
    }
    return b;
}

inline void showPanel(ui::PlotPanel &panel)
{
    panel.resize(1000, 700);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
}

/// A shown panel of drive 1 with 20 s of its samples.
struct ShownPanel {
    ui::TelemetryStore store;
    ui::PlotPanel panel{&store};
    ShownPanel()
    {
        panel.setDrives({1});
        showPanel(panel);
        store.append(batch(1, 0, 201, 0.1));
    }
};

} // namespace lk::plottest
