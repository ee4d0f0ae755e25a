package io.github.jdem846.bench;

import java.awt.Color;
import java.awt.Font;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.Styler;

/** One panel of the accuracy studies' plots (XChart): both axes logarithmic over given ranges, on white. */
final class LogLogPanel {

    static final int WIDTH = 560;
    static final int HEIGHT = 430;

    private LogLogPanel() {
    }

    /**
     * A panel without a legend.
     *
     * @param x        the x axis's {min, max}
     * @param y        the y axis's {min, max}
     * @param xPattern the x tick labels' decimal pattern
     * @param yPattern the y tick labels' decimal pattern
     */
    static XYChart create(String title, String xTitle, String yTitle, double[] x, double[] y, String xPattern,
                          String yPattern) {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(HEIGHT).title(title).xAxisTitle(xTitle)
                .yAxisTitle(yTitle).build();
        Styler st = chart.getStyler();
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setXAxisMin(x[0]);
        chart.getStyler().setXAxisMax(x[1]);
        chart.getStyler().setYAxisMin(y[0]);
        chart.getStyler().setYAxisMax(y[1]);
        chart.getStyler().setXAxisDecimalPattern(xPattern);
        chart.getStyler().setYAxisDecimalPattern(yPattern);
        chart.getStyler().setPlotGridLinesColor(new Color(220, 220, 220));
        st.setChartBackgroundColor(Color.WHITE);
        st.setPlotBackgroundColor(Color.WHITE);
        st.setChartTitleFont(new Font(Font.SANS_SERIF, Font.BOLD, 15));
        chart.getStyler().setAxisTitleFont(new Font(Font.SANS_SERIF, Font.PLAIN, 13));
        chart.getStyler().setAxisTickLabelsFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        st.setLegendVisible(false);
        return chart;
    }

    /**
     * Makes {@code chart} a legend panel: no axes, ticks, grid or border, its series' legend at the top left in
     * {@code fontSize}-point type (the series themselves drawn outside the axes' ranges).
     */
    static XYChart asLegend(XYChart chart, int fontSize) {
        hideAxes(chart);
        Styler st = chart.getStyler();
        st.setLegendVisible(true);
        st.setLegendPosition(Styler.LegendPosition.InsideNW);
        st.setLegendFont(new Font(Font.SANS_SERIF, Font.PLAIN, fontSize));
        st.setLegendBorderColor(Color.WHITE);
        return chart;
    }

    /** Hides the axes, ticks, grid lines and plot border of {@code chart} (for legend and blank panels). */
    static XYChart hideAxes(XYChart chart) {
        chart.getStyler().setAxisTicksVisible(false);
        chart.getStyler().setAxisTitlesVisible(false);
        chart.getStyler().setPlotGridLinesVisible(false);
        chart.getStyler().setPlotBorderVisible(false);
        return chart;
    }
}
