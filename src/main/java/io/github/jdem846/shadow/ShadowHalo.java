package io.github.jdem846.shadow;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;

/**
 * How much terrain beyond a tile can shade it. A ray leaving a cell of elevation ≥ {@code tileMin} rises above the
 * highest terrain {@code zMax} after (zMax − tileMin)/tan(elevation) metres toward the sun (the lower limb's
 * elevation for soft shadows), so a tile needs only that upstream halo, plus two cells all round for the bilinear
 * surface and the sweep's neighbouring lines, and {@link #FLOOR_STEPS} steps more for the sweep's floor. Curvature
 * only lowers distant terrain, so the same halo is enough.
 */
public final class ShadowHalo {

    /** Extra cells on every side for bilinear sampling and the sweep's neighbouring lines. */
    static final int MARGIN = 2;
    /**
     * The sweep ignores line heights more than this many steps' drop below the lowest terrain ({@link SunSweep}), so
     * its reach toward the sun is this many steps longer than a ray's.
     */
    static final int FLOOR_STEPS = 3;

    private ShadowHalo() {
    }

    /**
     * Horizontal distance in metres toward the sun beyond which no terrain can shade a cell of elevation
     * ≥ {@code tileMin}: 0 when the sun is at or below the horizon or at the zenith (nothing is traced) or when no
     * elevation is known; +∞ when the (lower limb of the) sun is at or below the horizon with soft shadows.
     *
     * @param zMax highest elevation of the whole DEM, in metres
     * @param tileMin lowest valid elevation in the tile, in metres
     * @param light where the light comes from
     * @param options curvature and soft shadows, which lengthen the distance
     * @return the distance in metres, ≥ 0, possibly +∞
     */
    public static double distanceMeters(double zMax, double tileMin, LightDirection light, ShadowOptions options) {
        double e = light.elevationDegrees();
        if (e <= 0 || e >= 90 || Double.isNaN(zMax) || Double.isNaN(tileMin)) {
            return 0;
        }
        double limb = options.softShadows() ? e - options.sunDiameterDegrees() / 2 : e;
        if (limb <= 0) {
            return Double.POSITIVE_INFINITY;
        }
        return Math.max(0, zMax - tileMin) / Math.tan(Math.toRadians(limb));
    }

    /**
     * The window of cells a computation for {@code tile} must read: the tile, the upstream halo toward the sun
     * and {@link #MARGIN} cells on every side, clipped to the grid.
     *
     * @param geometry the whole grid
     * @param zMax     highest elevation of the whole DEM
     * @param tileMin  lowest valid elevation in the tile
     * @param light where the light comes from, in the grid's frame
     * @param options curvature and soft shadows, which lengthen the halo
     * @param tile the cells to be computed
     * @return the cells to read, containing {@code tile}
     */
    public static CellWindow window(GridGeometry geometry, double zMax, double tileMin, LightDirection light,
                                    ShadowOptions options, CellWindow tile) {
        if (!tile.isInside(geometry.width(), geometry.height())) {
            throw new IllegalArgumentException("tile " + tile + " is not inside the " + geometry.width() + "×"
                    + geometry.height() + " grid");
        }
        double dist = distanceMeters(zMax, tileMin, light, options);
        int west = MARGIN;
        int east = MARGIN;
        int north = MARGIN;
        int south = MARGIN;
        if (dist > 0) {
            RayFrame frame = new RayFrame(geometry, zMax, light, options);
            double steps = (dist + FLOOR_STEPS * frame.maxMetresPerStep()) / frame.minMetresPerStep();
            int dc = cells(Math.abs(frame.ux) * steps);
            int dr = cells(Math.abs(frame.uy) * steps);
            if (frame.ux > 0) {
                east = add(east, dc);
            } else {
                west = add(west, dc);
            }
            if (frame.uy > 0) {
                south = add(south, dr);
            } else {
                north = add(north, dr);
            }
        }
        int c0 = (int) Math.max(0, (long) tile.col() - west);
        int r0 = (int) Math.max(0, (long) tile.row() - north);
        int c1 = (int) Math.min(geometry.width(), (long) tile.colEnd() + east);
        int r1 = (int) Math.min(geometry.height(), (long) tile.rowEnd() + south);
        return new CellWindow(c0, r0, c1 - c0, r1 - r0);
    }

    /**
     * {@link #window(GridGeometry, double, double, LightDirection, ShadowOptions, CellWindow)} for a DEM in memory.
     *
     * @param dem the elevations, whose maximum and the tile's minimum set the halo
     * @param light where the light comes from, in the grid's frame
     * @param options curvature and soft shadows, which lengthen the halo
     * @param tile the cells to be computed
     * @return the cells to read, containing {@code tile}
     */
    public static CellWindow window(Dem dem, LightDirection light, ShadowOptions options, CellWindow tile) {
        return window(dem.geometry(), dem.statistics().max(), tileMin(dem, tile), light, options, tile);
    }

    /** Lowest valid elevation in {@code tile} (NaN when it has none). */
    static double tileMin(Dem dem, CellWindow tile) {
        float[] v = dem.backingArray();
        float min = Float.POSITIVE_INFINITY;
        for (int r = tile.row(); r < tile.rowEnd(); r++) {
            int base = r * dem.width();
            for (int c = tile.col(); c < tile.colEnd(); c++) {
                float z = v[base + c];
                if (z < min) {
                    min = z;
                }
            }
        }
        return min == Float.POSITIVE_INFINITY ? Double.NaN : min;
    }

    /**
     * Halo length in major steps for the sweep (Integer.MAX_VALUE / 2 when unbounded): as far as terrain could still
     * raise a line above {@code floor}, the lowest height the sweep uses ({@link SunSweep#lowestFloor()}); the window
     * then equals the same cells of the whole grid.
     */
    static int sweepSteps(RayFrame frame, double floor, LightDirection light, ShadowOptions options) {
        double dist = distanceMeters(frame.zMax, floor, light, options);
        return cells(dist / frame.minMetresPerStep() + MARGIN);
    }

    private static int cells(double x) {
        if (!(x < Integer.MAX_VALUE / 2.0)) {
            return Integer.MAX_VALUE / 2;
        }
        return (int) Math.ceil(x) + 1;
    }

    private static int add(int a, int b) {
        return (int) Math.min(Integer.MAX_VALUE / 2, (long) a + b);
    }
}
