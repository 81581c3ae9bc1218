// Plot redraw cost: 3 series x 600,000 points (10 minutes at 1 kHz) drawn into a 1400x900
// chart through the decimated path, against handing every point to QtCharts. Prints one
// JSON line; run with QT_QPA_PLATFORM=offscreen (the run_bench_plot target sets it).

#include <plot/StripChart.h>
#include <plot/TelemetryStore.h>

#include <QtCharts/QChart>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#include <QtCore/QElapsedTimer>
#include <QtCore/QJsonDocument>
#include <QtCore/QJsonObject>
#include <QtGui/QImage>
#include <QtGui/QPainter>
#include <QtWidgets/QApplication>
#include <QtWidgets/QGraphicsScene>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>

using namespace lk::ui;

namespace {

constexpr int kPoints = 600000; // per series
constexpr int kWidth = 1400;
constexpr int kHeight = 900;
constexpr int kRedraws = 20;
constexpr int kNaiveRuns = 3;

double median(QVector<double> v)
{
    std::sort(v.begin(), v.end());
    const qsizetype n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

// CPU time of this thread: on a loaded machine wall time also counts waiting for a core.
double threadCpuMs()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

double timeMs(const std::function<void()> &f)
{
    QElapsedTimer timer;
    timer.start();
    f();
    return double(timer.nsecsElapsed()) / 1e6;
}

// A motor doing moves: speed steps, iq spikes at each step, noisy encoder.
double appendRecording(TelemetryStore &store)
{
    QElapsedTimer timer;
    timer.start();
    lk::bus::TelemetryBatch batch;
    for (int i = 0; i < kPoints; ++i) {
        const double t = i * 0.001;
        lk::bus::TelemetrySample s;
        s.id = 1;
        s.time = t;
        s.fields = lk::bus::TelemetryField::IqA | lk::bus::TelemetryField::Speed |
                   lk::bus::TelemetryField::Encoder;
        const double target = (int(t / 5) % 2 ? 300 : -300);
        s.speedDps = target + 20 * std::sin(t * 50);
        s.iqA = 0.3 * std::sin(t * 13) + (i % 5000 < 20 ? 8.0 : 0.0);
        s.encoder = int(t * 1000 + 7 * std::sin(t * 300)) % 16384;
        batch.append(s);
        if (batch.size() == 17) { // ~60 batches a second at 1 kHz
            store.append(batch);
            batch.clear();
        }
    }
    store.append(batch);
    return double(timer.nsecsElapsed()) / kPoints; // ns per sample
}

void render(StripChart &chart, QImage &image)
{
    QCoreApplication::processEvents(); // pending chart layout, as a real frame would run it
    image.fill(Qt::white);
    QPainter painter(&image);
    chart.scene()->render(&painter, image.rect(), image.rect());
}

} // namespace

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    TelemetryStore store;
    const double appendNs = appendRecording(store);

    StripChart chart;
    chart.setTraces({{1, TelemetryChannel::Torque, false},
                     {1, TelemetryChannel::Speed, false},
                     {1, TelemetryChannel::Encoder, false}},
                    StripChart::Coloring::ByChannel);
    // The view stays hidden: a shown view also paints itself into the platform's backing
    // store inside processEvents(), so every frame would be painted twice. The chart is
    // sized directly and its scene painted into our image: one paint per frame, as on screen.
    chart.chart()->resize(kWidth, kHeight);
    QImage image(kWidth, kHeight, QImage::Format_ARGB32_Premultiplied);
    const TimeSpan all = *store.timeSpan();
    for (int warm = 0; warm < 2; ++warm) { // sizes the chart, then decimates at its real width
        chart.refresh(store, all, true);
        render(chart, image);
    }
    const int columns = chart.plotColumns();

    // One frame: decimate + replace (refresh), the chart's deferred layout, then painting.
    struct Frame {
        double total, refresh, layout, paint, cpu;
    };
    auto redraw = [&](DecimationMethod method) {
        QVector<double> total, refresh, layout, paint, cpu;
        for (int i = 0; i < kRedraws; ++i) {
            const TimeSpan span{all.begin + i * 0.001, all.end}; // a new window every frame
            const double cpu0 = threadCpuMs();
            QElapsedTimer timer;
            timer.start();
            chart.refresh(store, span, true, method);
            const qint64 t1 = timer.nsecsElapsed();
            QCoreApplication::processEvents();
            const qint64 t2 = timer.nsecsElapsed();
            image.fill(Qt::white);
            {
                QPainter painter(&image);
                chart.scene()->render(&painter, image.rect(), image.rect());
            }
            const qint64 t3 = timer.nsecsElapsed();
            cpu.append(threadCpuMs() - cpu0);
            total.append(t3 / 1e6);
            refresh.append(t1 / 1e6);
            layout.append((t2 - t1) / 1e6);
            paint.append((t3 - t2) / 1e6);
        }
        return Frame{median(total), median(refresh), median(layout), median(paint), median(cpu)};
    };
    const Frame pyramidFrame = redraw(DecimationMethod::Pyramid);
    const Frame scanFrame = redraw(DecimationMethod::Scan);
    const double redrawMs = pyramidFrame.total;
    const double redrawScanMs = scanFrame.total;
    qsizetype drawn = 0;
    for (int i = 0; i < chart.traces().size(); ++i) {
        qsizetype n = 0;
        for (const QList<QPointF> &piece : chart.segments(i))
            n += piece.size();
        drawn = std::max(drawn, n);
    }

    auto decimateOnly = [&](DecimationMethod method) {
        QVector<double> ms;
        for (int i = 0; i < kRedraws; ++i) {
            ms.append(timeMs([&] {
                for (const auto channel : {TelemetryChannel::Torque, TelemetryChannel::Speed,
                                           TelemetryChannel::Encoder}) {
                    store.decimated(1, channel, all.begin + i * 0.001, all.end, columns, method);
                }
            }));
        }
        return median(ms);
    };
    const double pyramidMs = decimateOnly(DecimationMethod::Pyramid);
    const double scanMs = decimateOnly(DecimationMethod::Scan);

    // Naive: every point to QtCharts' own line series (the chart's legend series, which the
    // product leaves empty; lists built beforehand, so only QtCharts is measured).
    QVector<QList<QPointF>> everything;
    for (const PlotTrace &trace : chart.traces()) {
        const SampleRing *ring = store.ring(trace.driveId, trace.channel);
        QList<QPointF> points;
        points.reserve(ring->size());
        for (qsizetype i = 0; i < ring->size(); ++i) {
            points.append(ring->pointAt(i));
        }
        everything.append(points);
    }
    // The chart's series are only its legend, on no time axis (QtCharts would recompute their
    // domain at every frame): the naive baseline plots its points through them, on the axis.
    for (QLineSeries *series : chart.lineSeries())
        series->attachAxis(chart.timeAxis());
    QVector<double> naive;
    for (int run = 0; run < kNaiveRuns; ++run) {
        naive.append(timeMs([&] {
            for (int i = 0; i < everything.size(); ++i) {
                chart.lineSeries().at(i)->replace(everything.at(i));
            }
            render(chart, image);
        }));
    }
    const double naiveMs = median(naive);

    QJsonObject out;
    out["bench"] = "plot";
    out["plot_redraw_ms"] = redrawMs;
    out["plot_redraw_scan_ms"] = redrawScanMs;
    out["plot_naive_ms"] = naiveMs;
    out["plot_ratio"] = naiveMs / redrawMs;
    out["plot_redraw_cpu_ms"] = pyramidFrame.cpu;
    out["plot_redraw_scan_cpu_ms"] = scanFrame.cpu;
    out["frame_refresh_ms"] = pyramidFrame.refresh;
    out["frame_layout_ms"] = pyramidFrame.layout;
    out["frame_paint_ms"] = pyramidFrame.paint;
    out["decimate_pyramid_ms"] = pyramidMs;
    out["decimate_scan_ms"] = scanMs;
    out["append_ns_per_sample"] = appendNs;
    out["points"] = kPoints;
    out["series"] = 3;
    out["width"] = kWidth;
    out["height"] = kHeight;
    out["plot_columns"] = columns;
    out["points_drawn_per_series"] = qint64(drawn);
    out["redraws"] = kRedraws;
    out["naive_runs"] = kNaiveRuns;
    std::printf("%s\n", QJsonDocument(out).toJson(QJsonDocument::Compact).constData());
    return 0;
}
