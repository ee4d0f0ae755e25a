package io.github.jdem846.view;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Finer cells near the camera: the terrain is drawn from the coarse grid (the full-resolution grid box-averaged by
 * {@code decimation}), and around the camera from finer grids, each level a box-averaging by a power of two below
 * the one before, down to the full resolution. A level is used where a cell of the level above it would look
 * larger than {@value #PIXELS_PER_CELL} pixel: within {@code factor × cell size × focal length} metres of the camera.
 * Each level covers the rectangle of the full-resolution grid holding the coarse vertices that need it and the
 * camera can see (inside the picture, or just behind the near plane), inside the level above's rectangle; a level
 * of more than {@value #MAX_CELLS_PER_PIXEL} cells per picture pixel is not read, nor any finer one.
 *
 * <p>The seams: a coarser cell is left out only when it lies wholly inside the finer level's vertices, so the
 * coarser cells around a finer level overlap its edge, and the finer level has skirts hanging from its edge, as
 * deep as its range of heights (not below the base, and none at the grid's edge), textured as the edge: a ray
 * passing between the two surfaces meets a skirt or the overlapping coarse cell, so there are no cracks. Where a
 * level reaches the grid's edge, it has the base's walls in place of the coarse ones. Without a finer level, the mesh is the coarse grid's alone, drawn
 * exactly as a uniform mesh is.
 */
final class LevelsOfDetail {

    /** A coarser cell looking larger than this many pixels calls for the next finer level. */
    static final double PIXELS_PER_CELL = 1;
    /** Most cells a level may have per picture pixel. */
    static final int MAX_CELLS_PER_PIXEL = 4;

    private LevelsOfDetail() {
    }

    /** A finer level: its grid, and the box (in the grid's CRS) its vertices span. */
    private record Level(Dem dem, double west, double south, double east, double north, boolean[] onEdge) {
    }

    /**
     * The mesh of {@code terrain} (the coarse grid, {@code coarse}) with finer levels read from {@code source}
     * where the camera at {@code pose} needs them.
     *
     * @throws IOException when a level cannot be read
     */
    static Mesh mesh(Terrain terrain, Dem coarse, TerrainSource source, int decimation, Pose pose, int width,
                     int height, GridGeometry texture) throws IOException {
        List<Level> levels = levels(terrain, coarse, source, decimation, pose, width, height);
        if (levels.isEmpty()) {
            return Mesh.of(terrain);
        }
        return build(terrain, coarse, levels, texture);
    }

    /** {@return true when the coarse wall {@code item} hangs from two vertices inside the level (it is replaced)} */
    private static boolean wallInside(Mesh base, Dem coarse, Level level, int item) {
        GridGeometry g = coarse.geometry();
        int w = coarse.width();
        for (int corner = 0; corner < 2; corner++) {
            int i = base.items[4 * item + corner];
            double east = g.centerX(i % w);
            double north = g.centerY(i / w);
            if (east < level.west() || east > level.east() || north < level.south() || north > level.north()) {
                return false;
            }
        }
        return true;
    }

    /** The levels the camera needs, coarsest first. */
    private static List<Level> levels(Terrain terrain, Dem coarse, TerrainSource source, int decimation, Pose pose,
                                      int width, int height) throws IOException {
        List<Level> levels = new ArrayList<>();
        GridGeometry g = coarse.geometry();
        int midRow = coarse.height() / 2;
        double cellMeters = Math.max(g.cellWidthMeters(midRow), g.cellHeightMeters(midRow)) / decimation;
        int[] rect = {0, 0, source.width(), source.height()};
        int factor = decimation;
        while (factor > 1) {
            int finer = Integer.highestOneBit(factor - 1);
            double reach = factor * cellMeters * pose.focal / PIXELS_PER_CELL;
            int[] box = needed(terrain, pose, reach, 2 * decimation * cellMeters, width, height);
            if (box == null) {
                break;
            }
            int[] next = {Math.max(rect[0], (box[0] - 1) * decimation), Math.max(rect[1], (box[1] - 1) * decimation),
                Math.min(rect[0] + rect[2], (box[2] + 2) * decimation), Math.min(rect[1] + rect[3],
                    (box[3] + 2) * decimation)};
            int w = next[2] - next[0];
            int h = next[3] - next[1];
            if (w < 2 * finer || h < 2 * finer
                    || (double) w * h / ((double) finer * finer) > (double) MAX_CELLS_PER_PIXEL * width * height) {
                break;
            }
            Dem dem = source.read(next[0], next[1], w, h, finer);
            GridGeometry lg = dem.geometry();
            boolean[] onEdge = {next[0] == 0, next[1] == 0, next[2] == source.width(), next[3] == source.height()};
            levels.add(new Level(dem, lg.centerX(0), lg.centerY(dem.height() - 1), lg.centerX(dem.width() - 1),
                    lg.centerY(0), onEdge));
            rect = new int[] {next[0], next[1], w, h};
            factor = finer;
        }
        return levels;
    }

    /**
     * The box {firstCol, firstRow, lastCol, lastRow} of the coarse grid's vertices within {@code reach} metres of
     * the camera that it may see: in the picture (with a margin of a tenth of its size), or at or behind the near
     * plane and less than {@code cell} metres from the camera (the vertices of the triangles the near plane cuts
     * inside the picture); null when none.
     */
    private static int[] needed(Terrain terrain, Pose pose, double reach, double cell, int width, int height) {
        int[] box = {Integer.MAX_VALUE, Integer.MAX_VALUE, -1, -1};
        double mx = 0.1 * width;
        double my = 0.1 * height;
        for (int r = 0; r < terrain.height; r++) {
            for (int c = 0; c < terrain.width; c++) {
                int i = r * terrain.width + c;
                double x = terrain.x[i];
                double y = terrain.y[i];
                double z = terrain.z[i];
                if (Double.isNaN(z)) {
                    continue;
                }
                double dx = x - pose.eye[0];
                double dy = y - pose.eye[1];
                double dz = z - pose.eye[2];
                if (dx * dx + dy * dy + dz * dz > reach * reach) {
                    continue;
                }
                if (pose.depth(x, y, z) <= pose.near) {
                    if (dx * dx + dy * dy + dz * dz > cell * cell) {
                        continue;
                    }
                } else {
                    double sx = pose.screenX(x, y, z);
                    double sy = pose.screenY(x, y, z);
                    if (sx < -mx || sx > width + mx || sy < -my || sy > height + my) {
                        continue;
                    }
                }
                box[0] = Math.min(box[0], c);
                box[1] = Math.min(box[1], r);
                box[2] = Math.max(box[2], c);
                box[3] = Math.max(box[3], r);
            }
        }
        return box[2] < 0 ? null : box;
    }

    /** The coarse mesh without the cells the first level covers, then each level without those the next covers. */
    private static Mesh build(Terrain terrain, Dem coarse, List<Level> levels, GridGeometry texture) {
        float baseZ = terrain.baseLevel();
        Mesh base = Mesh.of(terrain);
        int vertices = base.vertexCount();
        int items = base.itemCount();
        for (Level level : levels) {
            Dem d = level.dem();
            vertices += d.width() * d.height() + 2 * perimeter(d.width(), d.height()).length;
            items += (d.width() - 1) * (d.height() - 1) + perimeter(d.width(), d.height()).length;
        }
        float[] x = Arrays.copyOf(base.x, vertices);
        float[] y = Arrays.copyOf(base.y, vertices);
        float[] z = Arrays.copyOf(base.z, vertices);
        float[] u = Arrays.copyOf(base.u, vertices);
        float[] v = Arrays.copyOf(base.v, vertices);
        int[] out = new int[4 * items];
        byte[] kinds = new byte[items];
        int k = 0;
        // the coarse cells the first level does not cover, then the base's walls
        GridGeometry cg = coarse.geometry();
        Level first = levels.get(0);
        for (int item = 0; item < base.itemCount(); item++) {
            if (item < base.gridCells) {
                int c = item % base.gridWidth;
                int r = item / base.gridWidth;
                if (covers(first, cg, c, r)) {
                    continue;
                }
            } else if (base.kinds[item] == Mesh.WALL && wallInside(base, coarse, first, item)) {
                continue;
            }
            System.arraycopy(base.items, 4 * item, out, 4 * k, 4);
            kinds[k++] = base.kinds[item];
        }
        int n = base.vertexCount();
        for (int l = 0; l < levels.size(); l++) {
            Dem d = levels.get(l).dem();
            Level next = l + 1 < levels.size() ? levels.get(l + 1) : null;
            GridGeometry g = d.geometry();
            int w = d.width();
            int h = d.height();
            float zMin = Float.POSITIVE_INFINITY;
            float zMax = Float.NEGATIVE_INFINITY;
            for (int r = 0; r < h; r++) {
                float vr = (float) ((texture.originY() - g.centerY(r)) / texture.cellHeight() - 0.5);
                for (int c = 0; c < w; c++) {
                    int i = n + r * w + c;
                    double[] p = place(terrain, g.centerX(c), g.centerY(r), d.get(c, r));
                    x[i] = (float) p[0];
                    y[i] = (float) p[1];
                    z[i] = (float) p[2];
                    u[i] = (float) ((g.centerX(c) - texture.originX()) / texture.cellWidth() - 0.5);
                    v[i] = vr;
                    if (!Float.isNaN(z[i])) {
                        zMin = Math.min(zMin, z[i]);
                        zMax = Math.max(zMax, z[i]);
                    }
                }
            }
            for (int r = 0; r + 1 < h; r++) {
                for (int c = 0; c + 1 < w; c++) {
                    if (next != null && covers(next, g, c, r)) {
                        continue;
                    }
                    int i = n + r * w + c;
                    out[4 * k] = i;
                    out[4 * k + 1] = i + 1;
                    out[4 * k + 2] = i + w;
                    out[4 * k + 3] = i + w + 1;
                    kinds[k++] = Mesh.CELL;
                }
            }
            // skirts; on the grid's edge, walls down to the base (when there is one) in place of the coarse ones
            int[] ring = perimeter(w, h);
            int bottom = n + w * h;
            float depth = zMin <= zMax ? zMax - zMin + 1 : 1;
            boolean[] edge = levels.get(l).onEdge();
            int wallBottom = bottom + ring.length;
            for (int j = 0; j < ring.length; j++) {
                int top = n + ring[j];
                for (int at : new int[] {bottom + j, wallBottom + j}) {
                    x[at] = x[top];
                    y[at] = y[top];
                    u[at] = u[top];
                    v[at] = v[top];
                }
                // not below the base, and none on the grid's edge, so a skirt never shows outside the terrain
                float skirt = onGridEdge(ring[j], w, h, edge) ? z[top] : z[top] - depth;
                z[bottom + j] = Float.isNaN(baseZ) ? skirt : Math.max(baseZ, skirt);
                z[wallBottom + j] = Float.isNaN(z[top]) ? Float.NaN : baseZ;
            }
            for (int j = 0; j < ring.length; j++) {
                int after = (j + 1) % ring.length;
                boolean wall = onGridEdge(ring[j], w, h, edge) && onGridEdge(ring[after], w, h, edge)
                        && sameSide(ring[j], ring[after], w, h, edge);
                if (wall && Float.isNaN(baseZ)) {
                    continue;
                }
                out[4 * k] = n + ring[j];
                out[4 * k + 1] = n + ring[after];
                int under = wall ? wallBottom : bottom;
                out[4 * k + 2] = under + j;
                out[4 * k + 3] = under + after;
                kinds[k++] = wall ? Mesh.WALL : Mesh.SKIRT;
            }
            n = wallBottom + ring.length;
        }
        return new Mesh(x, y, z, u, v, Arrays.copyOf(out, 4 * k), Arrays.copyOf(kinds, k), base.gridWidth,
                base.gridCells);
    }

    /** True when vertex {@code i} of a {@code w × h} level lies on a side of it that is on the grid's edge. */
    private static boolean onGridEdge(int i, int w, int h, boolean[] edge) {
        int c = i % w;
        int r = i / w;
        return edge[0] && c == 0 || edge[1] && r == 0 || edge[2] && c == w - 1 || edge[3] && r == h - 1;
    }

    /** True when vertices {@code i} and {@code j} (neighbours on the ring) lie on one side on the grid's edge. */
    private static boolean sameSide(int i, int j, int w, int h, boolean[] edge) {
        int ci = i % w;
        int ri = i / w;
        int cj = j % w;
        int rj = j / w;
        return edge[0] && ci == 0 && cj == 0 || edge[1] && ri == 0 && rj == 0
                || edge[2] && ci == w - 1 && cj == w - 1 || edge[3] && ri == h - 1 && rj == h - 1;
    }

    /** A point of the grid's CRS in the terrain's frame; NaN where it cannot be placed. */
    private static double[] place(Terrain terrain, double east, double north, float elevation) {
        if (Float.isNaN(elevation)) {
            return new double[] {Double.NaN, Double.NaN, Double.NaN};
        }
        try {
            return terrain.toLocal(east, north, elevation);
        } catch (IllegalArgumentException outsideProjection) {
            return new double[] {Double.NaN, Double.NaN, Double.NaN};
        }
    }

    /** True when the cell between vertices (c, r) and (c + 1, r + 1) of grid {@code g} lies inside the level. */
    private static boolean covers(Level level, GridGeometry g, int c, int r) {
        return g.centerX(c) >= level.west() && g.centerX(c + 1) <= level.east() && g.centerY(r + 1) >= level.south()
                && g.centerY(r) <= level.north();
    }

    /** The vertices of a {@code w × h} grid's edge in order around it. */
    private static int[] perimeter(int w, int h) {
        int[] ring = new int[2 * w + 2 * h - 4];
        int k = 0;
        for (int c = 0; c < w; c++) {
            ring[k++] = c;
        }
        for (int r = 1; r < h; r++) {
            ring[k++] = r * w + w - 1;
        }
        for (int c = w - 2; c >= 0; c--) {
            ring[k++] = (h - 1) * w + c;
        }
        for (int r = h - 2; r >= 1; r--) {
            ring[k++] = r * w;
        }
        return ring;
    }
}
