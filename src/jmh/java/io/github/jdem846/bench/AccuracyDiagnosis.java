package io.github.jdem846.bench;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowOptions;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.ForkJoinPool;
import javax.imageio.ImageIO;

/**
 * Where and how badly one method disagrees with {@code exact}: for each disagreeing cell, whether it lies on a
 * shadow edge of {@code exact} (a 4-neighbour differs), and how far the sun must move in elevation for {@code exact}
 * to agree (a sweep-shaded cell that exact lights is tested with a lower sun, the reverse with a higher one). A
 * disagreement that goes away within a few hundredths of a degree is a grazing ray — the two surfaces differ by
 * centimetres there; one that needs a large change is a real error of the method. Also counts disagreements
 * within {@link #EDGE_CELLS} cells of the grid's outer edge. Not a timing: no lock needed
 * beyond the shared one.
 */
final class AccuracyDiagnosis {

    /** Cells this close to the grid's outer edge count as "at the edge". */
    static final int EDGE_CELLS = 3;

    /** Elevation changes tried, degrees. */
    static final double[] DELTAS = {0.01, 0.03, 0.1, 0.3, 1, 3};

    private final Dem dem;
    private final ForkJoinPool pool;

    AccuracyDiagnosis(Dem dem, ForkJoinPool pool) {
        this.dem = dem;
        this.pool = pool;
    }

    /**
     * One row of the diagnosis table for {@code method} at one sun, over the given cells; optionally writes a map.
     *
     * @param map PNG to write (exact shadow dark grey, lit light grey, method-only shadow red, method-only light
     *            blue), or null
     */
    String row(StudyMethod method, double elevation, double azimuth, int[] cells, Path map) throws IOException {
        LightDirection light = new LightDirection(azimuth, elevation);
        float[] got = pick(method, light, cells);
        float[] ref = ShadowAlgorithm.EXACT.computeCells(dem, light, ShadowOptions.DEFAULTS, pool, cells);
        int[] bad = new int[cells.length];
        boolean[] falseShadow = new boolean[cells.length];
        int nb = 0;
        for (int q = 0; q < cells.length; q++) {
            boolean g = got[q] >= 0.5f;
            if (g != (ref[q] >= 0.5f)) {
                falseShadow[nb] = g;
                bad[nb++] = cells[q];
            }
        }
        bad = Arrays.copyOf(bad, nb);
        // shadow edge of exact: any 4-neighbour with the other answer
        int w = dem.width();
        int h = dem.height();
        int[] nbrs = new int[nb * 4];
        for (int q = 0; q < nb; q++) {
            int c = bad[q] % w;
            int r = bad[q] / w;
            nbrs[4 * q] = r * w + Math.max(0, c - 1);
            nbrs[4 * q + 1] = r * w + Math.min(w - 1, c + 1);
            nbrs[4 * q + 2] = Math.max(0, r - 1) * w + c;
            nbrs[4 * q + 3] = Math.min(h - 1, r + 1) * w + c;
        }
        float[] nref = ShadowAlgorithm.EXACT.computeCells(dem, light, ShadowOptions.DEFAULTS, pool, nbrs);
        int edge = 0;
        for (int q = 0; q < nb; q++) {
            boolean exactShadow = !falseShadow[q];
            for (int k = 0; k < 4; k++) {
                if ((nref[4 * q + k] >= 0.5f) != exactShadow) {
                    edge++;
                    break;
                }
            }
        }
        int nearEdge = 0;
        for (int q = 0; q < nb; q++) {
            int c = bad[q] % w;
            int r = bad[q] / w;
            nearEdge += Math.min(Math.min(c, w - 1 - c), Math.min(r, h - 1 - r)) < EDGE_CELLS ? 1 : 0;
        }
        // elevation change that makes exact agree
        int[] resolved = new int[DELTAS.length];
        boolean[] done = new boolean[nb];
        for (int d = 0; d < DELTAS.length; d++) {
            for (int sign : new int[] {-1, 1}) {
                boolean wantShadow = sign < 0;   // lower sun → look for exact shadow where the method shades
                int[] sub = subset(bad, falseShadow, done, wantShadow);
                if (sub.length == 0) {
                    continue;
                }
                double e = Math.max(0.001, Math.min(89.9, elevation + sign * DELTAS[d]));
                float[] moved = ShadowAlgorithm.EXACT.computeCells(dem, new LightDirection(azimuth, e),
                        ShadowOptions.DEFAULTS, pool, sub);
                int k = 0;
                for (int q = 0; q < nb; q++) {
                    if (!done[q] && falseShadow[q] == wantShadow) {
                        if ((moved[k++] >= 0.5f) == wantShadow) {
                            done[q] = true;
                            resolved[d]++;
                        }
                    }
                }
            }
        }
        if (map != null) {
            writeMap(map, cells, ref, bad, falseShadow);
        }
        int fs = 0;
        for (int q = 0; q < nb; q++) {
            fs += falseShadow[q] ? 1 : 0;
        }
        StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "| %s | %s | %d | %d / %d | %s | %s |",
                AccuracyPlot.fmt(elevation), AccuracyPlot.fmt(azimuth), nb, fs, nb - fs, share(edge, nb),
                share(nearEdge, nb)));
        int cum = 0;
        for (int d = 0; d < DELTAS.length; d++) {
            cum += resolved[d];
            sb.append(' ').append(share(cum, nb)).append(" |");
        }
        return sb.toString();
    }

    static String header() {
        StringBuilder sb = new StringBuilder("| elev. | azim. | cells ≠ exact | method shadow / method lit "
                + "| on an exact shadow edge | within " + EDGE_CELLS + " cells of the grid edge |");
        StringBuilder sep = new StringBuilder("|---:|---:|---:|---:|---:|---:|");
        for (double d : DELTAS) {
            sb.append(" agree within ±").append(AccuracyPlot.fmt(d)).append("° |");
            sep.append("---:|");
        }
        return sb + "\n" + sep;
    }

    private float[] pick(StudyMethod m, LightDirection light, int[] cells) {
        if (!m.wholeGrid()) {
            return m.algorithm.computeCells(dem, light, m.options, pool, cells);
        }
        float[] all = m.algorithm.compute(dem, light, m.options, pool).backingArray();
        float[] out = new float[cells.length];
        for (int q = 0; q < cells.length; q++) {
            out[q] = all[cells[q]];
        }
        return out;
    }

    private static int[] subset(int[] bad, boolean[] falseShadow, boolean[] done, boolean wantShadow) {
        return java.util.stream.IntStream.range(0, bad.length)
                .filter(q -> !done[q] && falseShadow[q] == wantShadow).map(q -> bad[q]).toArray();
    }

    private static String share(int n, int of) {
        return of == 0 ? "–" : String.format(Locale.ROOT, "%.0f %%", 100.0 * n / of);
    }

    private void writeMap(Path file, int[] cells, float[] ref, int[] bad, boolean[] falseShadow)
            throws IOException {
        int w = dem.width();
        int h = dem.height();
        int[] rgb = new int[w * h];
        Arrays.fill(rgb, 0xffffff);
        for (int q = 0; q < cells.length; q++) {
            rgb[cells[q]] = ref[q] >= 0.5f ? 0x707070 : 0xdddddd;
        }
        for (int q = 0; q < bad.length; q++) {           // 3×3 dots, so that single cells show
            int c = bad[q] % w;
            int r = bad[q] / w;
            for (int dr = -1; dr <= 1; dr++) {
                for (int dc = -1; dc <= 1; dc++) {
                    if (c + dc >= 0 && c + dc < w && r + dr >= 0 && r + dr < h) {
                        rgb[(r + dr) * w + c + dc] = falseShadow[q] ? 0xe00000 : 0x0040ff;
                    }
                }
            }
        }
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, w, h, rgb, 0, w);
        ImageIO.write(img, "png", file.toFile());
    }
}
