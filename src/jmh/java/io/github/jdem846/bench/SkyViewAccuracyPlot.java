package io.github.jdem846.bench;

import java.awt.BasicStroke;
import java.awt.Color;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.Marker;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * The sky-view study's error against run time with XChart: x = Mcells/s, y = absolute error of the factor, both
 * logarithmic; a panel per DEM with the sweep at D = 8 … 64 and the brute force at D = 32 with steps 1, ½, ¼ cell,
 * mean (filled) and maximum (crosses) error; same axes on every panel.
 */
final class SkyViewAccuracyPlot {

    /** Error drawn for a method that agreed exactly (log axes cannot show 0). */
    private static final double ZERO_ERROR = 1e-6;
    private static final Color SWEEP = new Color(220, 20, 20);
    private static final Color BRUTE = new Color(50, 110, 200);

    private SkyViewAccuracyPlot() {
    }

    /** Writes {@code images}/accuracy-skyview.png and returns its path. */
    static Path write(List<SkyViewAccuracyStudy.Point> points, List<String> dems, Path images) throws IOException {
        double[] xr = {Double.POSITIVE_INFINITY, 0};
        double[] yr = {Double.POSITIVE_INFINITY, 0};
        for (SkyViewAccuracyStudy.Point p : points) {
            xr[0] = Math.min(xr[0], p.mcellsPerSecond());
            xr[1] = Math.max(xr[1], p.mcellsPerSecond());
            yr[0] = Math.min(yr[0], Math.max(ZERO_ERROR, p.meanError()));
            yr[1] = Math.max(yr[1], p.maxError());
        }
        double[] x = {decadeBelow(xr[0]), decadeAbove(xr[1])};
        double[] y = {decadeBelow(yr[0]), decadeAbove(yr[1])};
        List<XYChart> panels = new ArrayList<>();
        for (String dem : dems) {
            XYChart chart = chart(dem + ": sky-view factor", x, y, false);
            addSeries(chart, points, dem, true, true);
            addSeries(chart, points, dem, true, false);
            addSeries(chart, points, dem, false, true);
            addSeries(chart, points, dem, false, false);
            panels.add(chart);
        }
        panels.add(legendPanel(x, y));
        int cols = Math.min(3, panels.size());
        int rows = (panels.size() + cols - 1) / cols;
        while (panels.size() < rows * cols) {
            XYChart blank = LogLogPanel.hideAxes(chart("", x, y, false));
            blank.getStyler().setChartTitleVisible(false);
            panels.add(blank);
        }
        Path file = images.resolve("accuracy-skyview.png");
        BitmapEncoder.saveBitmap(panels, rows, cols, file.toString(), BitmapEncoder.BitmapFormat.PNG);
        return file;
    }

    private static void addSeries(XYChart chart, List<SkyViewAccuracyStudy.Point> points, String dem, boolean sweep,
                                  boolean mean) {
        List<Double> xs = new ArrayList<>();
        List<Double> ys = new ArrayList<>();
        for (SkyViewAccuracyStudy.Point p : points) {
            if (p.dem().equals(dem) && p.method().startsWith("sweep") == sweep) {
                xs.add(p.mcellsPerSecond());
                ys.add(Math.max(ZERO_ERROR, mean ? p.meanError() : p.maxError()));
            }
        }
        if (!xs.isEmpty()) {
            style(chart.addSeries(label(sweep, mean), xs, ys), sweep, mean);
        }
    }

    private static String label(boolean sweep, boolean mean) {
        return (sweep ? "sweep, D = 8, 16, 32, 64 (right to left)" : "brute force, D = 32, step 1, ½, ¼ cell")
                + (mean ? ": mean" : ": maximum");
    }

    /** A panel with only the legend (series drawn outside its axes) and what the error is measured against. */
    private static XYChart legendPanel(double[] x, double[] y) {
        XYChart chart = LogLogPanel.asLegend(chart("legend", x, y, true), 13);
        for (boolean sweep : new boolean[] {true, false}) {
            for (boolean mean : new boolean[] {true, false}) {
                style(chart.addSeries(label(sweep, mean), new double[] {x[0] / 10}, new double[] {y[0] / 10}),
                        sweep, mean);
            }
        }
        XYSeries note = chart.addSeries("error: against the brute force, step ⅛ cell, same D",
                new double[] {x[0] / 10}, new double[] {y[0] / 10});
        note.setMarker(SeriesMarkers.NONE);
        note.setLineColor(Color.WHITE);
        return chart;
    }

    private static XYChart chart(String title, double[] x, double[] y, boolean legend) {
        XYChart chart = LogLogPanel.create(title, "Mcells/s (2 threads, log)", "absolute error of the factor (log)",
                x, y, "0.####", "0.######");
        chart.getStyler().setLegendVisible(legend);
        chart.getStyler().setMarkerSize(10);
        return chart;
    }

    private static void style(XYSeries series, boolean sweep, boolean mean) {
        Color color = sweep ? SWEEP : BRUTE;
        Marker marker = mean ? (sweep ? SeriesMarkers.TRIANGLE_UP : SeriesMarkers.CIRCLE) : SeriesMarkers.CROSS;
        series.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Line);
        series.setMarker(marker);
        series.setMarkerColor(color);
        series.setLineColor(color);
        series.setLineStyle(mean ? new BasicStroke(1.5f)
                : new BasicStroke(1f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10f, new float[] {4f, 4f}, 0f));
    }

    private static double decadeBelow(double v) {
        return Math.pow(10, Math.floor(Math.log10(v)));
    }

    private static double decadeAbove(double v) {
        return Math.pow(10, Math.ceil(Math.log10(v)));
    }
}
