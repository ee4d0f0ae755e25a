package io.github.jdem846.projection;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.render.RenderSettings;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;

/**
 * The warp against gdalwarp: our own unprojected relief of the Jacksboro DEM warped by us and by {@code gdalwarp
 * -r bilinear -et 0} (GDAL 3.6.2) to the same extent and size (testdata/golden/projection/README.md). Tolerance:
 * over the pixels both call opaque, mean |ΔDN| ≤ 1 per channel and 99 % of them within 8 DN on every channel;
 * pixels opaque in one and transparent in the other only along the outline (≤ 1.5 % of the picture). Also: the
 * same bytes for any thread count, known points on the right pixels, and no dark fringe along no-data.
 */
class PictureWarpTest {

    private static final Path GOLDEN = Path.of("testdata/golden/projection");
    private static final Path JACKSBORO = Path.of("testdata/dem/jacksboro_srtm3s_wgs84.tif");

    private static int[] argb(BufferedImage image) {
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    private record Comparison(double meanAbs, double within8, double outlineShare, int compared) {
    }

    private static Comparison compare(int[] ours, int[] theirs) {
        long sum = 0;
        int count = 0;
        int close = 0;
        int outline = 0;
        for (int i = 0; i < ours.length; i++) {
            int a = ours[i] >>> 24;
            int b = theirs[i] >>> 24;
            if (a == 0 || b == 0) {
                outline += a == b ? 0 : 1;
                continue;
            }
            int worst = 0;
            for (int shift = 0; shift <= 24; shift += 8) {
                int d = Math.abs(((ours[i] >>> shift) & 0xFF) - ((theirs[i] >>> shift) & 0xFF));
                sum += d;
                worst = Math.max(worst, d);
            }
            count++;
            close += worst <= 8 ? 1 : 0;
        }
        return new Comparison((double) sum / (4.0 * count), (double) close / count, (double) outline / ours.length,
                count);
    }

    private static void assertMatchesGdalwarp(ProjectionName name, ProjectedExtent extent, int width, int height,
                                              String golden) throws Exception {
        GridGeometry grid = DemReader.inspect(JACKSBORO).geometry();
        int[] source = argb(ImageIO.read(GOLDEN.resolve("jb_relief.png").toFile()));
        MapProjection projection = MapProjection.named(name, 0);
        ProjectedExtent ours = ProjectedExtent.of(grid, projection);
        assertEquals(extent.west(), ours.west(), 1e-6);
        assertEquals(extent.south(), ours.south(), 1e-6);
        assertEquals(extent.east(), ours.east(), 1e-6);
        assertEquals(extent.north(), ours.north(), 1e-6);
        int[] warped = PictureWarp.warp(source, grid, projection, extent, width, height, new RenderSettings(2, 256));
        BufferedImage reference = ImageIO.read(GOLDEN.resolve(golden).toFile());
        assertEquals(width, reference.getWidth());
        assertEquals(height, reference.getHeight());
        Comparison c = compare(warped, argb(reference));
        String report = name + ": " + c;
        System.out.println(report);
        assertTrue(c.compared() > width * height / 3, report);
        assertTrue(c.meanAbs() <= 1.0, report);
        assertTrue(c.within8() >= 0.99, report);
        assertTrue(c.outlineShare() <= 0.015, report);
    }

    @Test
    void winkelTripelMatchesGdalwarp() throws Exception {
        assertMatchesGdalwarp(ProjectionName.WINKEL_TRIPEL, new ProjectedExtent(-6993232.9226428615,
                4226888.211636712, -6954630.739160735, 4261164.783718582), 400, 355,
                "jb_relief_wintri_gdalwarp.png");
    }

    @Test
    void mollweideMatchesGdalwarp() throws Exception {
        assertMatchesGdalwarp(ProjectionName.MOLLWEIDE, new ProjectedExtent(-7391397.474211908, 4388437.364616936,
                -7344942.705416369, 4421049.826613518), 400, 281, "jb_relief_moll_gdalwarp.png");
    }

    private static byte[] gray(BufferedImage image) {
        byte[] out = new byte[image.getWidth() * image.getHeight()];
        int[] row = new int[image.getWidth()];
        for (int r = 0; r < image.getHeight(); r++) {
            image.getRaster().getSamples(0, r, image.getWidth(), 1, 0, row);
            for (int c = 0; c < row.length; c++) {
                out[r * row.length + c] = (byte) row[c];
            }
        }
        return out;
    }

    /**
     * Our hillshade of the DEM warped by us (no-data 0 left out of the bilinear blend) and by {@code gdalwarp -r
     * bilinear -srcnodata 0 -dstnodata 0 -et 0}: over the pixels both give data, mean |ΔDN| ≤ 1 and 99 % within
     * 8 DN; data in one and no-data in the other only along the outline (≤ 1.5 % of the picture).
     */
    private static void assertGrayMatchesGdalwarp(ProjectionName name, ProjectedExtent extent, int width,
                                                  int height, String golden) throws Exception {
        GridGeometry grid = DemReader.inspect(JACKSBORO).geometry();
        byte[] source = gray(ImageIO.read(GOLDEN.resolve("jb_hillshade.png").toFile()));
        MapProjection projection = MapProjection.named(name, 0);
        byte[] warped = PictureWarp.warpGray(source, 0, grid, projection, extent, width, height,
                new RenderSettings(2, 256));
        byte[] reference = gray(ImageIO.read(GOLDEN.resolve(golden).toFile()));
        assertEquals(width * height, reference.length);
        long sum = 0;
        int compared = 0;
        int close = 0;
        int outline = 0;
        for (int i = 0; i < warped.length; i++) {
            int a = warped[i] & 0xFF;
            int b = reference[i] & 0xFF;
            if (a == 0 || b == 0) {
                outline += (a == 0) == (b == 0) ? 0 : 1;
                continue;
            }
            sum += Math.abs(a - b);
            compared++;
            close += Math.abs(a - b) <= 8 ? 1 : 0;
        }
        String report = String.format(java.util.Locale.ROOT, "%s gray: mean |ΔDN| %.3f, within 8 DN %.4f, "
                + "outline %.4f, compared %d", name, (double) sum / compared, (double) close / compared,
                (double) outline / warped.length, compared);
        System.out.println(report);
        assertTrue(compared > width * height / 3, report);
        assertTrue((double) sum / compared <= 1.0, report);
        assertTrue((double) close / compared >= 0.99, report);
        assertTrue((double) outline / warped.length <= 0.015, report);
    }

    @Test
    void grayWinkelTripelMatchesGdalwarp() throws Exception {
        assertGrayMatchesGdalwarp(ProjectionName.WINKEL_TRIPEL, new ProjectedExtent(-6993232.9226428615,
                4226888.211636712, -6954630.739160735, 4261164.783718582), 400, 355,
                "jb_hillshade_wintri_gdalwarp.png");
    }

    @Test
    void grayMollweideMatchesGdalwarp() throws Exception {
        assertGrayMatchesGdalwarp(ProjectionName.MOLLWEIDE, new ProjectedExtent(-7391397.474211908,
                4388437.364616936, -7344942.705416369, 4421049.826613518), 400, 281,
                "jb_hillshade_moll_gdalwarp.png");
    }

    @Test
    void grayNoDataIsLeftOutOfTheBlend() throws Exception {
        GridGeometry grid = new GridGeometry(40, 30, 5, 50, 0.01, 0.01, CrsInfo.WGS84, PixelAnchor.CORNER);
        byte[] gray = new byte[40 * 30];
        for (int i = 0; i < gray.length; i++) {
            gray[i] = (byte) (i % 40 + i / 40 < 35 ? 200 : 0); // 200, then no-data
        }
        MapProjection projection = MapProjection.named(ProjectionName.ROBINSON, 0);
        ProjectedExtent extent = ProjectedExtent.of(grid, projection);
        int[] size = extent.pixels(97, 0);
        byte[] out = PictureWarp.warpGray(gray, 0, grid, projection, extent, size[0], size[1],
                new RenderSettings(2, 256));
        int data = 0;
        int none = 0;
        for (byte b : out) {
            int v = b & 0xFF;
            assertTrue(v == 0 || v == 200, "a pixel of " + v + " mixes data with no-data");
            data += v == 200 ? 1 : 0;
            none += v == 0 ? 1 : 0;
        }
        assertTrue(data > 0 && none > 0, data + " data, " + none + " no-data");
        byte[] mixed = PictureWarp.warpGray(gray, null, grid, projection, extent, size[0], size[1],
                new RenderSettings(2, 256));
        boolean blended = false;
        for (byte b : mixed) {
            blended |= (b & 0xFF) > 0 && (b & 0xFF) < 200;
        }
        assertTrue(blended, "without a no-data value, 0 is blended as a value");
    }

    /** A synthetic world picture in 1° cells (longitudes {@code west}…{@code west + 360}), not elevations. */
    private static GridGeometry world(double west) {
        return new GridGeometry(360, 180, west, 90, 1, 1, CrsInfo.WGS84, PixelAnchor.CORNER);
    }

    private static int[] gray(int cells) {
        int[] argb = new int[cells];
        java.util.Arrays.fill(argb, 0xFF808080);
        return argb;
    }

    @Test
    void knownPointsLandOnTheirPixels() throws Exception {
        GridGeometry grid = world(-180);
        double[][] points = {{30.5, 40.5}, {-120.5, -20.5}, {178.5, 0.5}, {-178.5, 60.5}, {0.5, 80.5}, {90.5, -84.5}};
        for (ProjectionName name : ProjectionName.values()) {
            MapProjection projection = MapProjection.named(name, name == ProjectionName.TRANSVERSE_MERCATOR ? 30 : 0);
            for (double[] p : points) {
                if (name == ProjectionName.TRANSVERSE_MERCATOR && Math.abs(p[0] - 30) > 40) {
                    continue; // transverse Mercator shows a band about its central meridian
                }
                if (name == ProjectionName.MERCATOR && Math.abs(p[1]) > 80) {
                    continue; // a 1° cell there spans dozens of rows, unevenly: its centroid is not its centre's image
                }
                int[] argb = gray(360 * 180);
                int col = (int) Math.floor(p[0] + 180);
                int row = (int) Math.floor(90 - p[1]);
                argb[row * 360 + col] = 0xFFFF0000;
                ProjectedExtent extent = ProjectedExtent.of(grid, projection);
                int[] size = extent.pixels(720, 0);
                int[] out = PictureWarp.warp(argb, grid, projection, extent, size[0], size[1],
                        new RenderSettings(2, 256));
                double sx = 0;
                double sy = 0;
                double sw = 0;
                for (int i = 0; i < out.length; i++) {
                    double red = ((out[i] >> 16) & 0xFF) - ((out[i] >> 8) & 0xFF); // 0 for gray, up to 127 for red
                    if ((out[i] >>> 24) > 0 && red > 0) {
                        sx += red * (i % size[0] + 0.5);
                        sy += red * (i / size[0] + 0.5);
                        sw += red;
                    }
                }
                String at = name + " at " + p[0] + ", " + p[1];
                assertTrue(sw > 0, at + ": the red cell is missing");
                double[] xy = {p[0], p[1]};
                GridMapping.of(grid, projection).toTarget(xy, 1);
                double expectedCol = (xy[0] - extent.west()) / (extent.width() / size[0]);
                double expectedRow = (extent.north() - xy[1]) / (extent.height() / size[1]);
                assertEquals(expectedCol, sx / sw, 1.0, at + " column");
                assertEquals(expectedRow, sy / sw, 1.0, at + " row");
            }
        }
    }

    @Test
    void worldOutlines() throws Exception {
        GridGeometry grid = world(-180);
        int[] argb = gray(360 * 180);
        for (ProjectionName name : new ProjectionName[] {ProjectionName.ROBINSON, ProjectionName.MOLLWEIDE,
                ProjectionName.HAMMER, ProjectionName.AITOFF, ProjectionName.WINKEL_TRIPEL,
                ProjectionName.WAGNER_VI}) {
            MapProjection projection = MapProjection.named(name, 0);
            ProjectedExtent extent = ProjectedExtent.of(grid, projection);
            double[] corner = {180, 0};
            GridMapping.of(grid, projection).toTarget(corner, 1);
            assertEquals(corner[0], extent.east(), extent.width() * 1e-6, name + ": the equator's end is the east edge");
            int[] size = extent.pixels(400, 0);
            int[] out = PictureWarp.warp(argb, grid, projection, extent, size[0], size[1], new RenderSettings(1, 256));
            int w = size[0];
            int h = size[1];
            assertEquals(0, out[0] >>> 24, name + ": the north-west corner is off the map");
            assertEquals(0, out[w * h - 1] >>> 24, name + ": the south-east corner is off the map");
            assertEquals(0xFF808080, out[(h / 2) * w + w / 2], name + ": the centre");
            assertEquals(0xFF808080, out[(h / 2) * w + 1], name + ": the west end of the equator");
            assertEquals(0xFF808080, out[(h / 2) * w + w - 2], name + ": the east end of the equator");
        }
        MapProjection mercator = MapProjection.named(ProjectionName.MERCATOR, 0);
        ProjectedExtent square = ProjectedExtent.of(grid, mercator);
        double[] top = {0, MapProjection.MERCATOR_LATITUDE_LIMIT};
        GridMapping.of(grid, mercator).toTarget(top, 1);
        assertEquals(top[1], square.north(), 1e-6, "Mercator's world ends at 85.0511°");
        assertEquals(-top[1], square.south(), 1e-6);
    }

    @Test
    void aWorldFrom0To360WrapsWithoutASeam() throws Exception {
        GridGeometry grid = world(0);
        int[] argb = gray(360 * 180);
        MapProjection projection = MapProjection.named(ProjectionName.EQUIRECTANGULAR, 0);
        ProjectedExtent extent = ProjectedExtent.of(grid, projection);
        assertEquals(-Math.PI * MapProjection.SPHERE_RADIUS, extent.west(), 1e-3);
        assertEquals(Math.PI * MapProjection.SPHERE_RADIUS, extent.east(), 1e-3);
        int[] out = PictureWarp.warp(argb, grid, projection, extent, 720, 360, new RenderSettings(2, 256));
        for (int i = 0; i < out.length; i++) {
            assertEquals(0xFF808080, out[i], "pixel " + (i % 720) + ", " + (i / 720));
        }
    }

    @Test
    void noDataEdgesDoNotDarken() throws Exception {
        GridGeometry grid = new GridGeometry(40, 30, 5, 50, 0.01, 0.01, CrsInfo.WGS84, PixelAnchor.CORNER);
        int[] argb = new int[40 * 30];
        for (int i = 0; i < argb.length; i++) {
            int col = i % 40;
            int row = i / 40;
            argb[i] = col + row < 35 ? 0xFFFFFFFF : 0x00000000; // white, then transparent black
        }
        MapProjection projection = MapProjection.named(ProjectionName.ROBINSON, 0);
        ProjectedExtent extent = ProjectedExtent.of(grid, projection);
        int[] out = PictureWarp.warp(argb, grid, projection, extent, 97, 0 + extent.pixels(97, 0)[1],
                new RenderSettings(2, 256));
        int partial = 0;
        for (int px : out) {
            int alpha = px >>> 24;
            if (alpha > 0) {
                assertEquals(0xFFFFFF, px & 0xFFFFFF, "a pixel with alpha " + alpha + " is not white");
                partial += alpha < 255 ? 1 : 0;
            }
        }
        assertTrue(partial > 0, "the edge blends alpha");
    }

    @Test
    void sameBytesForAnyThreadCount() throws Exception {
        GridGeometry grid = DemReader.inspect(JACKSBORO).geometry();
        int[] source = argb(ImageIO.read(GOLDEN.resolve("jb_relief.png").toFile()));
        MapProjection projection = MapProjection.named(ProjectionName.WINKEL_TRIPEL, 0);
        ProjectedExtent extent = ProjectedExtent.of(grid, projection);
        int[] one = PictureWarp.warp(source, grid, projection, extent, 300, 250, new RenderSettings(1, 256));
        for (int threads : new int[] {2, 3, 8}) {
            assertArrayEquals(one, PictureWarp.warp(source, grid, projection, extent, 300, 250,
                    new RenderSettings(threads, 256)), threads + " threads");
        }
    }
}
