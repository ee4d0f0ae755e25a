package io.github.jdem846.view;

/**
 * What the rasteriser draws: vertices in the terrain's local frame with texture positions, and quadrilateral items
 * of four vertices each (north-west, north-east, south-west, south-east; drawn as the triangles NW–NE–SE and
 * NW–SE–SW), in drawing order. An item is a cell of the terrain, a wall of the base (darkened) or a skirt hanging
 * from a finer level's edge (not darkened).
 */
final class Mesh {

    /** A cell of the terrain. */
    static final byte CELL = 0;
    /** A wall of the base, drawn darkened. */
    static final byte WALL = 1;
    /** A skirt under a level of detail's edge, hiding the seam to the coarser cells around it. */
    static final byte SKIRT = 2;

    final float[] x;
    final float[] y;
    final float[] z;
    final float[] u;
    final float[] v;
    /** Four vertex indices per item. */
    final int[] items;
    /** {@link #CELL}, {@link #WALL} or {@link #SKIRT} per item. */
    final byte[] kinds;
    /** The first items are the cells of a grid this many cells across, row by row ({@link #gridCells} of them). */
    final int gridWidth;
    final int gridCells;

    Mesh(float[] x, float[] y, float[] z, float[] u, float[] v, int[] items, byte[] kinds, int gridWidth,
         int gridCells) {
        this.x = x;
        this.y = y;
        this.z = z;
        this.u = u;
        this.v = v;
        this.items = items;
        this.kinds = kinds;
        this.gridWidth = gridWidth;
        this.gridCells = gridCells;
    }

    /** The terrain's cells, row by row, then its base's walls. */
    static Mesh of(Terrain terrain) {
        int w = terrain.width;
        int cells = (terrain.width - 1) * (terrain.height - 1);
        cells = Math.max(0, cells);
        int walls = terrain.perimeter.length;
        int[] items = new int[4 * (cells + walls)];
        byte[] kinds = new byte[cells + walls];
        int k = 0;
        for (int r = 0; r + 1 < terrain.height; r++) {
            for (int c = 0; c + 1 < w; c++) {
                int i = r * w + c;
                items[4 * k] = i;
                items[4 * k + 1] = i + 1;
                items[4 * k + 2] = i + w;
                items[4 * k + 3] = i + w + 1;
                k++;
            }
        }
        int n = terrain.size();
        for (int j = 0; j < walls; j++) {
            int next = (j + 1) % walls;
            items[4 * k] = terrain.perimeter[j];
            items[4 * k + 1] = terrain.perimeter[next];
            items[4 * k + 2] = n + j;
            items[4 * k + 3] = n + next;
            kinds[k++] = WALL;
        }
        return new Mesh(terrain.x, terrain.y, terrain.z, terrain.u, terrain.v, items, kinds, Math.max(0, w - 1),
                cells);
    }

    /** @return the number of vertices */
    int vertexCount() {
        return x.length;
    }

    /** @return the number of items */
    int itemCount() {
        return kinds.length;
    }
}
