package io.github.jdem846.bench;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import java.util.Arrays;

/**
 * The sweep the issue warns about, for comparison only: shadow heights carried from one row (or column) to the next
 * toward the shade and linearly re-interpolated at every step. A cell's shadow height is the previous line's
 * max(terrain, shadow height) read at the fractional position one major step toward the sun, less the drop of one
 * step; the cell is in shadow when that exceeds its elevation. Each step blurs the carried heights sideways, so at
 * fractional azimuths shadows smear; there is no test inside the first step. Uses the metric cell size of the middle
 * row (as {@code RayFrame} does) and one step length for the whole grid, so it is meant for projected grids.
 */
final class RowByRowSweep {

    private RowByRowSweep() {
    }

    /** Shadowed (1) or lit (0) per cell, row-major; no-data cells 0. */
    static float[] compute(Dem dem, LightDirection light) {
        GridGeometry g = dem.geometry();
        int w = dem.width();
        int h = dem.height();
        double cw = g.cellWidthMeters(h / 2);
        double ch = g.cellHeightMeters(h / 2);
        double az = Math.toRadians(light.azimuthDegrees());
        double gx = Math.sin(az) / cw;
        double gy = -Math.cos(az) / ch;
        boolean xMajor = Math.abs(gx) >= Math.abs(gy);
        double ux = xMajor ? Math.signum(gx) : gx / Math.abs(gy);
        double uy = xMajor ? gy / Math.abs(gx) : Math.signum(gy);
        double drop = Math.tan(Math.toRadians(light.elevationDegrees())) * Math.hypot(ux * cw, uy * ch);
        int nMaj = xMajor ? w : h;
        int nMin = xMajor ? h : w;
        int dirMaj = (int) (xMajor ? ux : uy);          // +1: the sun lies toward larger indices
        double shift = xMajor ? uy : ux;                  // minor displacement of one step toward the sun
        if (Math.abs(shift) < 1e-12) {
            shift = 0;                                    // cos 90° is 6e-17, not 0
        }
        float[] v = dem.backingArray();
        float[] out = new float[v.length];
        double[] carried = new double[nMin];              // max(z, shadow height) of the line upstream
        double[] shadow = new double[nMin];
        Arrays.fill(carried, Double.NEGATIVE_INFINITY);
        int first = dirMaj > 0 ? nMaj - 1 : 0;
        for (int step = 0; step < nMaj; step++) {
            int i = first - dirMaj * step;
            for (int j = 0; j < nMin; j++) {
                double s = Double.NEGATIVE_INFINITY;
                if (step > 0) {
                    double p = j + shift;
                    if (p >= 0 && p <= nMin - 1) {
                        int j0 = (int) Math.floor(p);
                        int j1 = Math.min(j0 + 1, nMin - 1);
                        double f = p - j0;
                        double a = carried[j0];
                        double b = carried[j1];
                        s = f == 0 ? a : (a == Double.NEGATIVE_INFINITY || b == Double.NEGATIVE_INFINITY
                                ? Math.max(a, b) : a + (b - a) * f);
                        s -= drop;
                    }
                }
                shadow[j] = s;
                int cell = xMajor ? j * w + i : i * w + j;
                float z = v[cell];
                out[cell] = z == z && s > z ? 1f : 0f;
            }
            for (int j = 0; j < nMin; j++) {
                float z = v[xMajor ? j * w + i : i * w + j];
                carried[j] = z == z ? Math.max(z, shadow[j]) : shadow[j];
            }
        }
        return out;
    }
}
