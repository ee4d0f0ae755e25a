package io.github.jdem846.bench;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.Marker;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * Work-precision plots with XChart: x = Mcells/s, y = % of cells in disagreement with {@code exact}, both
 * logarithmic, one series per method; one PNG per DEM with a panel per sun elevation.
 */
final class AccuracyPlot {

    /** Disagreement drawn for a method that agreed on every evaluated cell (log axes cannot show 0). */
    static final double ZERO_PERCENT = 1e-3;


    private AccuracyPlot() {
    }

    /** Writes {@code images}/accuracy-DEM.png and returns its path. */
    static Path write(AccuracySummary s, String dem, Path images) throws IOException {
        List<Double> elevations = s.elevations(dem);
        double[] xr = {Double.POSITIVE_INFINITY, 0};
        double[] yr = {Double.POSITIVE_INFINITY, 0};
        for (double e : elevations) {
            for (StudyMethod m : plotted()) {
                AccuracySummary.Cell c = s.cell(dem, e, m);
                if (c != null) {
                    double y = percent(c);
                    xr[0] = Math.min(xr[0], c.mcellsPerSecond());
                    xr[1] = Math.max(xr[1], c.mcellsPerSecond());
                    yr[0] = Math.min(yr[0], y);
                    yr[1] = Math.max(yr[1], y);
                }
            }
        }
        double xMin = Math.pow(10, Math.floor(Math.log10(xr[0])));
        double xMax = Math.pow(10, Math.ceil(Math.log10(xr[1])));
        double yMin = Math.pow(10, Math.floor(Math.log10(yr[0])));
        double yMax = Math.pow(10, Math.ceil(Math.log10(yr[1])));
        List<XYChart> panels = new ArrayList<>();
        for (int p = 0; p < elevations.size(); p++) {
            double e = elevations.get(p);
            XYChart chart = chart(String.format(Locale.ROOT, "%s: sun elevation %s°", dem, fmt(e)),
                    xMin, xMax, yMin, yMax, false);
            for (StudyMethod m : plotted()) {
                AccuracySummary.Cell c = s.cell(dem, e, m);
                if (c != null) {
                    XYSeries series = chart.addSeries(m.label, new double[] {c.mcellsPerSecond()},
                            new double[] {percent(c)});
                    style(series, m);
                }
            }
            panels.add(chart);
        }
        panels.add(legendPanel(dem));
        int cols = Math.min(3, panels.size());
        int rows = (panels.size() + cols - 1) / cols;
        while (panels.size() < rows * cols) {
            XYChart blank = legendPanel("");
            blank.getStyler().setLegendVisible(false);
            blank.getStyler().setChartTitleVisible(false);
            panels.add(blank);
        }
        Path file = images.resolve("accuracy-" + dem + ".png");
        BitmapEncoder.saveBitmap(panels, rows, cols, file.toString(), BitmapEncoder.BitmapFormat.PNG);
        return file;
    }

    /** A panel with only the legend (series drawn outside its axes) and notes on reading the plots. */
    private static XYChart legendPanel(String dem) {
        XYChart chart = LogLogPanel.asLegend(chart(dem + ": legend", 1, 10, 1, 10, true), 14);
        for (StudyMethod m : plotted()) {
            style(chart.addSeries(m.label, new double[] {1e-6}, new double[] {1e-6}), m);
        }
        return chart;
    }

    private static XYChart chart(String title, double xMin, double xMax, double yMin, double yMax,
                                 boolean legend) {
        XYChart chart = LogLogPanel.create(title, "Mcells/s (2 threads, log)",
                "% cells ≠ exact (log; 0 drawn at 0.001)", new double[] {xMin, xMax}, new double[] {yMin, yMax},
                "0.###", "0.###");
        Styler st = chart.getStyler();
        st.setLegendVisible(legend);
        st.setLegendPosition(Styler.LegendPosition.InsideNE);
        st.setLegendFont(new Font(Font.SANS_SERIF, Font.PLAIN, 10));
        st.setLegendBackgroundColor(new Color(255, 255, 255, 215));
        st.setMarkerSize(11);
        return chart;
    }

    private static List<StudyMethod> plotted() {
        List<StudyMethod> l = new ArrayList<>(List.of(StudyMethod.values()));
        l.remove(StudyMethod.EXACT);
        return l;
    }

    private static double percent(AccuracySummary.Cell c) {
        return Math.max(ZERO_PERCENT, 100 * c.meanFraction());
    }

    private static void style(XYSeries series, StudyMethod m) {
        Color color;
        Marker marker;
        switch (m) {
            case MARCH_ARTICLE -> {
                color = Color.BLACK;
                marker = SeriesMarkers.DIAMOND;
            }
            case MARCH_1_NEAREST -> {
                color = new Color(140, 180, 230);
                marker = SeriesMarkers.CIRCLE;
            }
            case MARCH_HALF_NEAREST -> {
                color = new Color(50, 110, 200);
                marker = SeriesMarkers.CIRCLE;
            }
            case MARCH_QUARTER_NEAREST -> {
                color = new Color(10, 30, 120);
                marker = SeriesMarkers.CIRCLE;
            }
            case MARCH_1_BILINEAR -> {
                color = new Color(150, 220, 140);
                marker = SeriesMarkers.SQUARE;
            }
            case MARCH_HALF_BILINEAR -> {
                color = new Color(40, 160, 60);
                marker = SeriesMarkers.SQUARE;
            }
            case MARCH_QUARTER_BILINEAR -> {
                color = new Color(0, 80, 20);
                marker = SeriesMarkers.SQUARE;
            }
            case SWEEP -> {
                color = new Color(220, 20, 20);
                marker = SeriesMarkers.TRIANGLE_UP;
            }
            case SWEEP_NO_FIRST_CELL -> {
                color = new Color(245, 150, 0);
                marker = SeriesMarkers.TRIANGLE_DOWN;
            }
            case SWEEP_NEAREST -> {
                color = new Color(190, 0, 190);
                marker = SeriesMarkers.CROSS;
            }
            default -> throw new AssertionError(m);
        }
        series.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
        series.setMarker(marker);
        series.setMarkerColor(color);
        series.setLineColor(color);
        series.setLineStyle(new BasicStroke(0f));
    }

    static String fmt(double d) {
        return d == Math.rint(d) ? Long.toString((long) d) : Double.toString(d);
    }
}
