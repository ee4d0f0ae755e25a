package io.github.jdem846.overlay;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.GridGeometry;
import java.awt.Color;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Where {@link OverlayPainter} puts hand-made test geometries (testdata/overlay/README.md): a line along a known row
 * of cells, a polygon with a hole over known cells, a point at a cell centre, on the Jacksboro grid (WGS 84); the
 * same features from a shapefile made by ogr2ogr; and lon/lat shapes on the UTM Big Tujunga grid against
 * gdal_rasterize of the same shapes into the same grid.
 */
class OverlayPainterTest {

    static final Path JACKSBORO = Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif");
    static final Path TUJUNGA = Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif");
    static final Path DIR = Path.of("testdata/overlay");
    static final Path JACKSBORO_SHAPES = DIR.resolve("jacksboro_test_shapes.geojson");

    /** Opaque white lines 1 px wide, no fill, points of radius 3. */
    static final OverlayStyle LINE = new OverlayStyle(Color.WHITE, 1, null, 3);

    static GridGeometry grid(Path dem) throws IOException {
        return DemReader.inspect(dem).geometry();
    }

    /** The overlays painted onto a fully transparent picture of {@code grid}. */
    static int[] paint(GridGeometry grid, List<Overlay> overlays) {
        int[] argb = new int[grid.width() * grid.height()];
        OverlayPainter.of(overlays, grid).paintRows(argb, 0, grid.height());
        return argb;
    }

    static int alpha(int[] argb, int width, int col, int row) {
        return argb[row * width + col] >>> 24;
    }

    static Overlay only(Overlay all, Class<?> type) {
        return new Overlay(all.name(), all.geometries().stream().filter(type::isInstance).toList(), all.crs(),
                all.style());
    }

    @Test
    void aLineAlongACellRowLandsOnThatRow() throws IOException {
        GridGeometry grid = grid(JACKSBORO);
        Overlay line = only(OverlayFiles.read(JACKSBORO_SHAPES, LINE), org.locationtech.jts.geom.LineString.class);
        int[] argb = paint(grid, List.of(line));
        int w = grid.width();
        for (int col = 60; col <= 340; col++) {
            double sum = 0;
            double weighted = 0;
            for (int row = 0; row < grid.height(); row++) {
                int a = alpha(argb, w, col, row);
                sum += a;
                weighted += a * row;
            }
            assertTrue(sum > 0, "column " + col + " is crossed");
            assertEquals(100, weighted / sum, 1.0, "column " + col);
            assertTrue(alpha(argb, w, col, 100) >= 200, "row 100 covered at column " + col);
            assertEquals(0, alpha(argb, w, col, 98));
            assertEquals(0, alpha(argb, w, col, 102));
        }
        assertEquals(0, alpha(argb, w, 40, 100), "nothing beyond the line's end");
    }

    @Test
    void aPolygonFillCoversItsCellsButNotItsHole() throws IOException {
        GridGeometry grid = grid(JACKSBORO);
        OverlayStyle fillOnly = new OverlayStyle(Color.BLACK, 0, Color.BLUE, 0);
        Overlay polygon = only(OverlayFiles.read(JACKSBORO_SHAPES, fillOnly), org.locationtech.jts.geom.Polygon.class);
        int[] argb = paint(grid, List.of(polygon));
        long covered = java.util.Arrays.stream(argb).filter(p -> (p >>> 24) >= 128).count();
        int expected = 100 * 80 - 40 * 40;   // columns 60..159 × rows 180..259, less the hole 90..129 × 200..239
        assertEquals(expected, covered, expected * 0.02);
        int w = grid.width();
        assertEquals(255, alpha(argb, w, 60, 180));
        assertEquals(255, alpha(argb, w, 159, 259));
        assertEquals(0, alpha(argb, w, 59, 200));
        assertEquals(0, alpha(argb, w, 110, 220), "the hole stays empty");
        assertEquals(0, alpha(argb, w, 160, 200));
    }

    @Test
    void aPointIsADiscCentredOnItsCell() throws IOException {
        GridGeometry grid = grid(JACKSBORO);
        Overlay point = only(OverlayFiles.read(JACKSBORO_SHAPES, LINE), org.locationtech.jts.geom.Point.class);
        int[] argb = paint(grid, List.of(point));
        int w = grid.width();
        double sum = 0;
        double sx = 0;
        double sy = 0;
        for (int i = 0; i < argb.length; i++) {
            int a = argb[i] >>> 24;
            sum += a;
            sx += a * (i % w);
            sy += a * (i / w);
        }
        assertEquals(300, sx / sum, 0.25);
        assertEquals(250, sy / sum, 0.25);
        assertEquals(Math.PI * 9 * 255, sum, 0.1 * Math.PI * 9 * 255, "a disc of radius 3 px");
    }

    @Test
    void aShapefileDrawsAsTheGeoJsonItWasMadeFrom() throws IOException {
        GridGeometry grid = grid(JACKSBORO);
        OverlayStyle style = new OverlayStyle(Color.RED, 2, new Color(0, 0, 255, 100), 4);
        int[] fromGeoJson = paint(grid, List.of(OverlayFiles.read(JACKSBORO_SHAPES, style)));
        int[] fromShapefiles = paint(grid, List.of(
                OverlayFiles.read(DIR.resolve("jacksboro_test_shapes_lines.shp"), style),
                OverlayFiles.read(DIR.resolve("jacksboro_test_shapes_polygons.shp"), style),
                OverlayFiles.read(DIR.resolve("jacksboro_test_shapes_points.shp"), style)));
        assertTrue(java.util.Arrays.stream(fromGeoJson).filter(p -> p != 0).count() > 6000);
        assertArrayEquals(fromGeoJson, fromShapefiles);
    }

    @Test
    void lonLatShapesLandOnTheUtmGridWhereGdalRasterizePutsThem() throws IOException {
        GridGeometry grid = grid(TUJUNGA);
        Overlay shapes = OverlayFiles.read(DIR.resolve("bigtujunga_test_shapes.geojson"),
                new OverlayStyle(Color.WHITE, 1, Color.WHITE, 0));
        int w = grid.width();
        int h = grid.height();

        boolean[] lineGolden = golden("line");
        int[] line = paint(grid, List.of(only(shapes, org.locationtech.jts.geom.LineString.class)));
        int goldenCount = 0;
        for (int i = 0; i < lineGolden.length; i++) {
            if (lineGolden[i]) {
                goldenCount++;
                assertTrue(near(line, w, h, i % w, i / w, 1, 1), "gdal's line pixel " + i % w + "," + i / w);
            }
            if ((line[i] >>> 24) >= 128) {
                assertTrue(near(lineGolden, w, h, i % w, i / w), "our line pixel " + i % w + "," + i / w);
            }
        }
        assertTrue(goldenCount > 900, "the golden line has " + goldenCount + " pixels");

        boolean[] polygonGolden = golden("polygon");
        int[] polygon = paint(grid, List.of(only(shapes, org.locationtech.jts.geom.Polygon.class)
                .withStyle(new OverlayStyle(Color.WHITE, 0, Color.WHITE, 0))));
        int expected = 0;
        int ours = 0;
        int differ = 0;
        for (int i = 0; i < polygon.length; i++) {
            boolean in = (polygon[i] >>> 24) >= 128;
            expected += polygonGolden[i] ? 1 : 0;
            ours += in ? 1 : 0;
            differ += in != polygonGolden[i] ? 1 : 0;
            if (in != polygonGolden[i]) {
                assertTrue(near(polygon, w, h, i % w, i / w, 1, 0) && near(polygonGolden, w, h, i % w, i / w)
                        && !allSet(polygonGolden, w, h, i % w, i / w), "pixel " + i % w + "," + i / w
                        + " differs away from the edge");
            }
        }
        assertEquals(expected, ours, expected * 0.01);
        assertTrue(differ < expected * 0.02, differ + " pixels differ");
    }

    /** A gdal_rasterize golden mask (255 inside) of the Big Tujunga grid. */
    static boolean[] golden(String name) throws IOException {
        Dem d = DemReader.read(DIR.resolve("bigtujunga_test_shapes_" + name + "_gdal_rasterize.tif"));
        boolean[] mask = new boolean[d.width() * d.height()];
        for (int r = 0; r < d.height(); r++) {
            for (int c = 0; c < d.width(); c++) {
                mask[r * d.width() + c] = d.get(c, r) == 255;
            }
        }
        return mask;
    }

    /** True when a pixel within {@code reach} (Chebyshev) has alpha ≥ {@code minAlpha}... or below it for 0. */
    static boolean near(int[] argb, int w, int h, int col, int row, int reach, int minAlpha) {
        for (int r = Math.max(0, row - reach); r <= Math.min(h - 1, row + reach); r++) {
            for (int c = Math.max(0, col - reach); c <= Math.min(w - 1, col + reach); c++) {
                int a = argb[r * w + c] >>> 24;
                if (minAlpha > 0 ? a >= minAlpha : a < 128) {
                    return true;
                }
            }
        }
        return false;
    }

    static boolean near(boolean[] mask, int w, int h, int col, int row) {
        for (int r = Math.max(0, row - 1); r <= Math.min(h - 1, row + 1); r++) {
            for (int c = Math.max(0, col - 1); c <= Math.min(w - 1, col + 1); c++) {
                if (mask[r * w + c]) {
                    return true;
                }
            }
        }
        return false;
    }

    static boolean allSet(boolean[] mask, int w, int h, int col, int row) {
        for (int r = Math.max(0, row - 1); r <= Math.min(h - 1, row + 1); r++) {
            for (int c = Math.max(0, col - 1); c <= Math.min(w - 1, col + 1); c++) {
                if (!mask[r * w + c]) {
                    return false;
                }
            }
        }
        return true;
    }
}
