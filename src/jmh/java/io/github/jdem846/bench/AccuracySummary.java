package io.github.jdem846.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Stream;

/**
 * The study's CSV rows, aggregated over azimuths per DEM, elevation and method.
 *
 * @param rows every row read
 */
record AccuracySummary(List<AccuracyRow> rows) {

    /**
     * One DEM, elevation and method over all its azimuths.
     *
     * @param meanFraction mean disagreeing fraction over the azimuths
     * @param meanSe       standard error of that mean (0 when every cell was compared): the mean of the azimuths'
     *                     binomial standard errors, an upper bound, since every azimuth uses the same sample
     * @param worst        the row of the azimuth with the largest disagreement
     * @param meanSeconds  mean over the azimuths of the fastest run time
     * @param timedCells   cells per timed run
     * @param azimuths     number of azimuths
     * @param falseShadow  cells over all azimuths that the method shades and exact lights
     * @param falseLit     cells over all azimuths that the method lights and exact shades
     * @param exactShadow  cells over all azimuths in shadow according to exact
     * @param evalCells    cells compared over all azimuths
     */
    record Cell(double meanFraction, double meanSe, AccuracyRow worst, double meanSeconds, long timedCells,
                int azimuths, long falseShadow, long falseLit, long exactShadow, long evalCells) {

        /** Share of the compared cells in shadow according to exact, over all azimuths. */
        double shadowFraction() {
            return (double) exactShadow / evalCells;
        }

        double mcellsPerSecond() {
            return timedCells / meanSeconds / 1e6;
        }
    }

    /** Reads every {@code *.csv} in {@code dir} (lines starting with # are comments). */
    static AccuracySummary read(Path dir) throws IOException {
        List<AccuracyRow> rows = new ArrayList<>();
        List<Path> files;
        try (Stream<Path> s = Files.list(dir)) {
            files = s.filter(p -> p.toString().endsWith(".csv")).sorted().toList();
        }
        for (Path f : files) {
            for (String line : Files.readAllLines(f, StandardCharsets.UTF_8)) {
                if (line.isBlank() || line.startsWith("#") || line.equals(AccuracyRow.HEADER)) {
                    continue;
                }
                rows.add(AccuracyRow.parse(line));
            }
        }
        if (rows.isEmpty()) {
            throw new IOException("no accuracy rows in " + dir + "/*.csv; run 'measure' first");
        }
        return new AccuracySummary(rows);
    }

    /** DEM names present, in {@link StudyDem#NAMES} order (unknown names last). */
    List<String> dems() {
        TreeSet<String> names = new TreeSet<>(Comparator.comparingInt(AccuracySummary::order)
                .thenComparing(Comparator.naturalOrder()));
        rows.forEach(r -> names.add(r.dem()));
        return new ArrayList<>(names);
    }

    private static int order(String dem) {
        int i = StudyDem.NAMES.indexOf(dem);
        return i < 0 ? Integer.MAX_VALUE : i;
    }

    /** Elevations measured for {@code dem}, ascending. */
    List<Double> elevations(String dem) {
        return rows.stream().filter(r -> r.dem().equals(dem)).map(AccuracyRow::elevation).distinct().sorted()
                .toList();
    }

    /** Azimuths measured for {@code dem}, ascending. */
    List<Double> azimuths(String dem) {
        return rows.stream().filter(r -> r.dem().equals(dem)).map(AccuracyRow::azimuth).distinct().sorted()
                .toList();
    }

    /** Any row of {@code dem} (for its cell counts). */
    AccuracyRow any(String dem) {
        return rows.stream().filter(r -> r.dem().equals(dem)).findFirst().orElseThrow();
    }

    /** The aggregate over azimuths; null when that combination was not measured. */
    Cell cell(String dem, double elevation, StudyMethod method) {
        List<AccuracyRow> rs = rows.stream().filter(r -> r.dem().equals(dem) && r.elevation() == elevation
                && r.method() == method).toList();
        if (rs.isEmpty()) {
            return null;
        }
        double sum = 0;
        double se = 0;
        double secs = 0;
        long fs = 0;
        long fl = 0;
        long xs = 0;
        long ev = 0;
        AccuracyRow worst = rs.get(0);
        for (AccuracyRow r : rs) {
            sum += r.fraction();
            se += r.standardError();
            secs += r.seconds();
            fs += r.falseShadow();
            fl += r.falseLit();
            xs += r.exactShadow();
            ev += r.evalCells();
            if (r.fraction() > worst.fraction()) {
                worst = r;
            }
        }
        int n = rs.size();
        return new Cell(sum / n, se / n, worst, secs / n, rs.get(0).timedCells(), n, fs, fl, xs, ev);
    }

    /** Per-azimuth rows of one DEM, elevation and method, by azimuth. */
    Map<Double, AccuracyRow> byAzimuth(String dem, double elevation, StudyMethod method) {
        Map<Double, AccuracyRow> m = new TreeMap<>();
        rows.stream().filter(r -> r.dem().equals(dem) && r.elevation() == elevation && r.method() == method)
                .forEach(r -> m.put(r.azimuth(), r));
        return m;
    }
}
