package io.github.jdem846.bench;

import java.util.Locale;

/**
 * One measurement of the accuracy study: one method on one DEM for one sun, compared with {@code exact} on the
 * evaluated cells (every valid cell, or a seeded random sample of them).
 *
 * @param dem          DEM name ({@link StudyDem#name()})
 * @param gridCells    width × height of the DEM
 * @param evalCells    valid cells compared with the reference
 * @param exhaustive   true when every valid cell was compared, false for a random sample
 * @param elevation    sun elevation, degrees
 * @param azimuth      sun azimuth, degrees clockwise from north
 * @param method       the method
 * @param disagree     cells where the method and {@code exact} disagree (shadow = fraction ≥ ½)
 * @param falseShadow  of those, cells the method shades and {@code exact} lights
 * @param falseLit     of those, cells the method lights and {@code exact} shades
 * @param exactShadow  evaluated cells in shadow according to {@code exact}
 * @param timedCells   cells computed by one timed run (the whole grid for sweeps, else the evaluated cells)
 * @param seconds      fastest wall time of the timed runs
 * @param runs         number of timed runs
 */
record AccuracyRow(String dem, long gridCells, long evalCells, boolean exhaustive, double elevation, double azimuth,
                   StudyMethod method, long disagree, long falseShadow, long falseLit, long exactShadow,
                   long timedCells, double seconds, int runs) {

    static final String HEADER = "dem,grid_cells,eval_cells,exhaustive,elevation,azimuth,method,disagree,"
            + "false_shadow,false_lit,exact_shadow,timed_cells,seconds,runs";

    /** Disagreeing fraction of the evaluated cells. */
    double fraction() {
        return evalCells == 0 ? 0 : (double) disagree / evalCells;
    }

    /** Binomial standard error of {@link #fraction()}: 0 when exhaustive (no sampling error). */
    double standardError() {
        if (exhaustive || evalCells == 0) {
            return 0;
        }
        double p = fraction();
        return Math.sqrt(p * (1 - p) / evalCells);
    }

    /** Millions of cells per second. */
    double mcellsPerSecond() {
        return timedCells / seconds / 1e6;
    }

    String toCsv() {
        return String.format(Locale.ROOT, "%s,%d,%d,%b,%s,%s,%s,%d,%d,%d,%d,%d,%.6f,%d", dem, gridCells, evalCells,
                exhaustive, num(elevation), num(azimuth), method.key(), disagree, falseShadow, falseLit,
                exactShadow, timedCells, seconds, runs);
    }

    static AccuracyRow parse(String line) {
        String[] f = line.split(",");
        if (f.length != 14) {
            throw new IllegalArgumentException("expected 14 fields, got " + f.length + ": " + line);
        }
        return new AccuracyRow(f[0], Long.parseLong(f[1]), Long.parseLong(f[2]), Boolean.parseBoolean(f[3]),
                Double.parseDouble(f[4]), Double.parseDouble(f[5]), StudyMethod.ofKey(f[6]), Long.parseLong(f[7]),
                Long.parseLong(f[8]), Long.parseLong(f[9]), Long.parseLong(f[10]), Long.parseLong(f[11]),
                Double.parseDouble(f[12]), Integer.parseInt(f[13]));
    }

    private static String num(double d) {
        return d == Math.rint(d) ? Long.toString((long) d) : Double.toString(d);
    }
}
