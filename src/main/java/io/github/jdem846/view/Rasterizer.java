package io.github.jdem846.view;

/**
 * Draws the terrain's triangles, two per cell (the diagonal from the cell's north-west to its south-east vertex),
 * and those of the base's walls, two per edge segment, into a depth buffer with perspective-correct texture positions. The picture is cut into bands of {@value #BAND}
 * rows; each band owns its pixels and draws the triangles binned to it in the same order (cell by cell, row 0
 * first), every pixel tested at its own centre, and the nearer of two fragments wins (the first drawn on a tie): so
 * a pixel's value does not depend on how many bands there are or which thread draws them.
 *
 * <p>A triangle crossing the camera's near plane ({@link Pose#near}) is clipped to the part in front of it (one or
 * two triangles, whose new vertices lie on the near plane); one wholly behind it is not drawn. A new vertex is
 * computed from its edge's two vertices in the same order whichever triangle the edge belongs to, so neighbouring
 * clipped triangles meet exactly.
 */
final class Rasterizer {

    /** Rows per band. */
    static final int BAND = 32;

    /** {@link #iz} of a vertex behind the near plane. */
    private static final float BEHIND = -1;

    private final Mesh mesh;
    private final Pose pose;
    private final int width;
    private final int height;
    private final float[] sx;
    private final float[] sy;
    private final float[] iz;
    private int[] binStart;
    private int[] binCells;

    /**
     * Projects the terrain's vertices: a vertex that is no-data gets NaN and its triangles are not drawn; one not
     * beyond {@link Pose#near} is marked, and its triangles are clipped.
     */
    Rasterizer(Terrain terrain, Pose pose, int width, int height) {
        this(Mesh.of(terrain), pose, width, height);
    }

    /** Projects the vertices of {@code mesh}, as {@link #Rasterizer(Terrain, Pose, int, int)}. */
    Rasterizer(Mesh mesh, Pose pose, int width, int height) {
        this.mesh = mesh;
        this.pose = pose;
        this.width = width;
        this.height = height;
        int n = mesh.vertexCount();
        sx = new float[n];
        sy = new float[n];
        iz = new float[n];
        for (int i = 0; i < n; i++) {
            double x = mesh.x[i];
            double y = mesh.y[i];
            double z = mesh.z[i];
            double d = pose.depth(x, y, z);
            if (Double.isNaN(z) || !(d > pose.near)) {
                sx[i] = Float.NaN;
                sy[i] = Float.NaN;
                iz[i] = Double.isNaN(z) || Double.isNaN(d) ? Float.NaN : BEHIND;
                continue;
            }
            sx[i] = (float) pose.screenX(x, y, z);
            sy[i] = (float) pose.screenY(x, y, z);
            iz[i] = (float) (1 / d);
        }
        bin();
    }

    /** @return the number of bands */
    int bands() {
        return (height + BAND - 1) / BAND;
    }

    /** The four vertices of item {@code k}. */
    private int[] corners(int k) {
        return new int[] {mesh.items[4 * k], mesh.items[4 * k + 1], mesh.items[4 * k + 2], mesh.items[4 * k + 3]};
    }

    /** Lists, band by band in item order (cells, then walls), the items whose projection may touch the band. */
    private void bin() {
        int bands = bands();
        int items = mesh.itemCount();
        int[] first = new int[Math.max(0, items)];
        int[] last = new int[Math.max(0, items)];
        int[] count = new int[bands + 1];
        for (int k = 0; k < items; k++) {
            float minX = Float.POSITIVE_INFINITY;
            float maxX = Float.NEGATIVE_INFINITY;
            float minY = Float.POSITIVE_INFINITY;
            float maxY = Float.NEGATIVE_INFINITY;
            int valid = 0;
            int[] q = corners(k);
            boolean crossesNearPlane = iz[q[0]] == BEHIND || iz[q[1]] == BEHIND || iz[q[2]] == BEHIND
                    || iz[q[3]] == BEHIND;
            if (crossesNearPlane) {
                double[] clipped = new double[CLIPPED];
                for (int[] t : new int[][] {{q[0], q[1], q[3]}, {q[0], q[3], q[2]}}) {
                    int corners = clip(t[0], t[1], t[2], clipped);
                    for (int m = 0; m < corners; m++) {
                        valid = 4;
                        minX = (float) Math.min(minX, clipped[m * 5]);
                        maxX = (float) Math.max(maxX, clipped[m * 5]);
                        minY = (float) Math.min(minY, clipped[m * 5 + 1]);
                        maxY = (float) Math.max(maxY, clipped[m * 5 + 1]);
                    }
                }
            }
            for (int j : crossesNearPlane ? new int[0] : q) {
                if (!Float.isNaN(sx[j])) {
                    valid++;
                    minX = Math.min(minX, sx[j]);
                    maxX = Math.max(maxX, sx[j]);
                    minY = Math.min(minY, sy[j]);
                    maxY = Math.max(maxY, sy[j]);
                }
            }
            first[k] = -1;
            if (valid < 3 || maxX < 0 || minX > width || maxY < 0 || minY > height) {
                continue;
            }
            int b0 = (int) Math.max(0, Math.floor((minY - 0.5) / BAND));
            int b1 = (int) Math.min(bands - 1, Math.floor((maxY - 0.5) / BAND));
            if (b1 < b0) {
                continue;
            }
            first[k] = b0;
            last[k] = b1;
            for (int b = b0; b <= b1; b++) {
                count[b + 1]++;
            }
        }
        binStart = new int[bands + 1];
        for (int b = 0; b < bands; b++) {
            binStart[b + 1] = binStart[b] + count[b + 1];
        }
        binCells = new int[binStart[bands]];
        int[] fill = binStart.clone();
        for (int k = 0; k < items; k++) {
            for (int b = first[k]; b >= 0 && b <= last[k]; b++) {
                binCells[fill[b]++] = k;
            }
        }
    }

    /**
     * The cells whose triangles may be drawn: {firstCol, firstRow, lastCol, lastRow} of the terrain's cells that
     * overlap the picture, or null when none does.
     */
    int[] drawnCells() {
        int cellsAcross = mesh.gridWidth;
        int cells = mesh.gridCells;
        int[] box = {Integer.MAX_VALUE, Integer.MAX_VALUE, -1, -1};
        for (int k : binCells) {
            if (k >= cells) {
                continue;
            }
            int c = k % cellsAcross;
            int r = k / cellsAcross;
            box[0] = Math.min(box[0], c);
            box[1] = Math.min(box[1], r);
            box[2] = Math.max(box[2], c);
            box[3] = Math.max(box[3], r);
        }
        return box[2] < 0 ? null : box;
    }

    /**
     * Draws band {@code band}: for each of its pixels covered by terrain, the inverse depth (0 where none) and the
     * texture position.
     *
     * @param depth inverse depths of the whole picture, 0 to start with
     * @param texU  texture x of the whole picture
     * @param texV  texture y of the whole picture
     * @param wall  true where the nearest fragment is the base's wall
     */
    void drawBand(int band, float[] depth, float[] texU, float[] texV, boolean[] wall) {
        int y0 = band * BAND;
        int y1 = Math.min(height, y0 + BAND);
        for (int e = binStart[band]; e < binStart[band + 1]; e++) {
            int k = binCells[e];
            int[] q = corners(k);
            boolean isWall = mesh.kinds[k] == Mesh.WALL;
            // a cell: NW, NE, SE and NW, SE, SW; a wall: top, next top, next base and top, next base, base
            triangle(q[0], q[1], q[3], y0, y1, depth, texU, texV, wall, isWall);
            triangle(q[0], q[3], q[2], y0, y1, depth, texU, texV, wall, isWall);
        }
    }

    /** Doubles a clipped triangle takes: up to 4 vertices of (screen x, screen y, 1/depth, u, v). */
    private static final int CLIPPED = 20;

    private void triangle(int a, int b, int c, int y0, int y1, float[] depth, float[] texU, float[] texV,
                          boolean[] wall, boolean isWall) {
        if (iz[a] == BEHIND || iz[b] == BEHIND || iz[c] == BEHIND) {
            double[] p = new double[CLIPPED];
            int count = clip(a, b, c, p);
            for (int m = 2; m < count; m++) {
                int i = (m - 1) * 5;
                int j = m * 5;
                fill(p[0], p[1], p[2], p[3], p[4], p[i], p[i + 1], p[i + 2], p[i + 3], p[i + 4],
                        p[j], p[j + 1], p[j + 2], p[j + 3], p[j + 4], y0, y1, depth, texU, texV, wall, isWall);
            }
            return;
        }
        fill(sx[a], sy[a], iz[a], mesh.u[a], mesh.v[a], sx[b], sy[b], iz[b], mesh.u[b], mesh.v[b],
                sx[c], sy[c], iz[c], mesh.u[c], mesh.v[c], y0, y1, depth, texU, texV, wall, isWall);
    }

    /**
     * The part of triangle {@code a b c} beyond the near plane, as a convex polygon of 0, 3 or 4 vertices, each
     * (screen x, screen y, 1/depth, u, v) into {@code out}; 0 when a vertex is no-data or all are behind.
     */
    private int clip(int a, int b, int c, double[] out) {
        if (Float.isNaN(iz[a]) || Float.isNaN(iz[b]) || Float.isNaN(iz[c])) {
            return 0;
        }
        int[] t = {a, b, c};
        int n = 0;
        for (int e = 0; e < 3; e++) {
            int p = t[e];
            int q = t[(e + 1) % 3];
            boolean pIn = iz[p] != BEHIND;
            if (pIn) {
                out[n * 5] = sx[p];
                out[n * 5 + 1] = sy[p];
                out[n * 5 + 2] = iz[p];
                out[n * 5 + 3] = mesh.u[p];
                out[n * 5 + 4] = mesh.v[p];
                n++;
            }
            if (pIn != (iz[q] != BEHIND)) {
                onNearPlane(Math.min(p, q), Math.max(p, q), out, n * 5);
                n++;
            }
        }
        return n;
    }

    /** The point where the edge from vertex {@code i} to vertex {@code j} crosses the near plane. */
    private void onNearPlane(int i, int j, double[] out, int at) {
        double xi = mesh.x[i];
        double yi = mesh.y[i];
        double zi = mesh.z[i];
        double xj = mesh.x[j];
        double yj = mesh.y[j];
        double zj = mesh.z[j];
        double di = pose.depth(xi, yi, zi);
        double dj = pose.depth(xj, yj, zj);
        double f = (pose.near - di) / (dj - di);
        double cx = pose.cameraX(xi, yi, zi) + f * (pose.cameraX(xj, yj, zj) - pose.cameraX(xi, yi, zi));
        double cy = pose.cameraY(xi, yi, zi) + f * (pose.cameraY(xj, yj, zj) - pose.cameraY(xi, yi, zi));
        out[at] = pose.centerX + pose.focal * cx / pose.near;
        out[at + 1] = pose.centerY - pose.focal * cy / pose.near;
        out[at + 2] = 1 / pose.near;
        out[at + 3] = mesh.u[i] + f * (mesh.u[j] - mesh.u[i]);
        out[at + 4] = mesh.v[i] + f * (mesh.v[j] - mesh.v[i]);
    }

    /** Fills a triangle given by its vertices' screen positions, inverse depths and texture positions. */
    private void fill(double ax, double ay, double za, double tua, double tva, double bx, double by, double zb,
                      double tub, double tvb, double cx, double cy, double zc, double tuc, double tvc, int y0,
                      int y1, float[] depth, float[] texU, float[] texV, boolean[] wall, boolean isWall) {
        double area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
        if (!(Math.abs(area) > 1e-12)) {
            return; // degenerate, or a vertex is NaN
        }
        int xs = (int) Math.max(0, Math.ceil(Math.min(ax, Math.min(bx, cx)) - 0.5));
        int xe = (int) Math.min(width - 1, Math.floor(Math.max(ax, Math.max(bx, cx)) - 0.5));
        int ys = (int) Math.max(y0, Math.ceil(Math.min(ay, Math.min(by, cy)) - 0.5));
        int ye = (int) Math.min(y1 - 1, Math.floor(Math.max(ay, Math.max(by, cy)) - 0.5));
        double ua = tua * za;
        double ub = tub * zb;
        double uc = tuc * zc;
        double va = tva * za;
        double vb = tvb * zb;
        double vc = tvc * zc;
        double inverse = 1 / area;
        for (int py = ys; py <= ye; py++) {
            double y = py + 0.5;
            for (int px = xs; px <= xe; px++) {
                double x = px + 0.5;
                double w0 = ((cx - bx) * (y - by) - (cy - by) * (x - bx)) * inverse;
                double w1 = ((ax - cx) * (y - cy) - (ay - cy) * (x - cx)) * inverse;
                double w2 = ((bx - ax) * (y - ay) - (by - ay) * (x - ax)) * inverse;
                if (w0 < 0 || w1 < 0 || w2 < 0) {
                    continue;
                }
                double z = w0 * za + w1 * zb + w2 * zc;
                int p = py * width + px;
                if (z > depth[p]) {
                    depth[p] = (float) z;
                    texU[p] = (float) ((w0 * ua + w1 * ub + w2 * uc) / z);
                    texV[p] = (float) ((w0 * va + w1 * vb + w2 * vc) / z);
                    wall[p] = isWall;
                }
            }
        }
    }
}
