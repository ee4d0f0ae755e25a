package io.github.jdem846.tiles;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.drape.Drape;
import io.github.jdem846.drape.DrapeImage;
import io.github.jdem846.geo.WebMercator;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.render.ColorLayer;
import io.github.jdem846.render.Scene;
import io.github.jdem846.shadow.CellWindow;
import io.github.jdem846.tint.ColorRamp;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A drape on map tiles (testdata/golden/drape, see its README): gdaldem's colour relief of a crop of Big Tujunga
 * with the default tint's stops in metres (in UTM 11N, the tiles in Web Mercator) draped over another tint gives the
 * tiles of the default tint (within 3 levels per channel and 0.3 on average: gdaldem rounds its colours with +0.45,
 * and interpolates colours where the tiles interpolate elevations; measured 2 and 0.11); the tiles of a zoom side by side are the drape sampled once over the whole zoom's grid;
 * where the image is over 3 times finer than a tile pixel, it is read every k-th pixel, k measured on the DEM.
 */
class TileDrapeTest {

    static final Path DEM = Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif");
    static final Path IMAGE = Path.of("testdata/golden/drape/bigtujunga_crop_table2_utm.tif");
    /** The crop the image covers: DEM cells 420–739 × 120–359 (gdal_translate -srcwin 420 120 320 240). */
    static final int CROP_COL = 420;
    static final int CROP_ROW = 120;
    static final int CROP_W = 320;
    static final int CROP_H = 240;
    static final int S = WebMercatorTile.SIZE;

    @TempDir
    Path dir;

    /** Every tile of zoom {@code z} in {@code tiles}, laid out over {@code range}; 0 where none was written. */
    static int[] mosaic(Path tiles, TileRange range) throws IOException {
        int nx = range.maxX() - range.minX() + 1;
        int ny = range.maxY() - range.minY() + 1;
        int[] argb = new int[nx * S * ny * S];
        for (int ty = 0; ty < ny; ty++) {
            for (int tx = 0; tx < nx; tx++) {
                Path f = tiles.resolve(range.z() + "/" + (range.minX() + tx) + "/" + (range.minY() + ty) + ".png");
                if (!Files.exists(f)) {
                    continue;
                }
                BufferedImage img = ImageIO.read(f.toFile());
                for (int r = 0; r < S; r++) {
                    for (int c = 0; c < S; c++) {
                        argb[(ty * S + r) * nx * S + tx * S + c] = img.getRGB(c, r);
                    }
                }
            }
        }
        return argb;
    }

    static TileRange range(int z) throws IOException {
        GridGeometry g = DemReader.inspect(DEM).geometry();
        return TileRange.covering(g.latLonExtent().orElseThrow(), z);
    }

    /** The whole tile range of zoom {@code z} as one grid, a window of the zoom's world. */
    static GridGeometry picture(TileRange range) {
        return new ZoomGrid(range.z()).window(range.minX() * S, range.minY() * S,
                (range.maxX() - range.minX() + 1) * S, (range.maxY() - range.minY() + 1) * S);
    }

    /**
     * For each pixel of {@code picture}, whether its centre lies at least {@code margin} DEM cells inside the crop
     * the image covers: Web Mercator to longitude/latitude by the closed formulas, then to UTM 11N by the DEM's
     * locator.
     */
    static boolean[] insideCrop(GridGeometry picture, double margin) throws IOException {
        GridGeometry dem = DemReader.inspect(DEM).geometry();
        int n = picture.width() * picture.height();
        double[] p = utm(picture);
        boolean[] inside = new boolean[n];
        for (int i = 0; i < n; i++) {
            double col = (p[2 * i] - dem.originX()) / dem.cellWidth();
            double row = (dem.originY() - p[2 * i + 1]) / dem.cellHeight();
            inside[i] = col >= CROP_COL + margin && col <= CROP_COL + CROP_W - margin
                    && row >= CROP_ROW + margin && row <= CROP_ROW + CROP_H - margin;
        }
        return inside;
    }

    /** The UTM 11N x, y of the centre of every pixel of {@code picture}, row by row. */
    static double[] utm(GridGeometry picture) throws IOException {
        int n = picture.width() * picture.height();
        double[] p = new double[2 * n];
        for (int r = 0; r < picture.height(); r++) {
            for (int c = 0; c < picture.width(); c++) {
                int i = r * picture.width() + c;
                p[2 * i] = WebMercator.longitude(picture.centerX(c));
                p[2 * i + 1] = WebMercator.latitude(picture.centerY(r));
            }
        }
        DemReader.inspect(DEM).geometry().geoLocator().orElseThrow().fromLonLat(p, n);
        return p;
    }

    @Test
    void gdaldemsReliefOfTheDefaultTintDrapedOverAnotherGivesTheTilesOfTheDefaultTint() throws Exception {
        int z = 12;   // tile pixels of about 31.6 m on the ground, the DEM's cells 30 m: no averaging of the DEM
        TileJob job = TileJob.of(DEM, new ZoomRange(z, z));
        Scene etopo = Scene.defaults().withTint(ColorRamp.named("etopo1"));
        Path tint = dir.resolve("tint");
        Path draped = dir.resolve("draped");
        Path other = dir.resolve("etopo1");
        job.run(tint, JobListener.NONE);
        job.withScene(etopo.withDrape(Drape.of(List.of(IMAGE)))).run(draped, JobListener.NONE);
        job.withScene(etopo).run(other, JobListener.NONE);
        TileRange range = range(z);
        int[] a = mosaic(tint, range);
        int[] b = mosaic(draped, range);
        int[] e = mosaic(other, range);
        boolean[] inside = insideCrop(picture(range), 2);
        boolean[] near = insideCrop(picture(range), -1);   // the crop grown by a DEM cell on each side
        int n = 0;
        int worst = 0;
        long sum = 0;
        int fromImage = 0;
        int outside = 0;
        int outsideSame = 0;
        for (int i = 0; i < a.length; i++) {
            if (a[i] >>> 24 != 255) {
                continue;   // no tile, or no data
            }
            if (!near[i]) {
                outside++;
                outsideSame += b[i] == e[i] ? 1 : 0;
            }
            if (!inside[i]) {
                continue;
            }
            n++;
            fromImage += b[i] != e[i] ? 1 : 0;
            for (int shift = 0; shift <= 16; shift += 8) {
                int d = Math.abs((a[i] >> shift & 0xFF) - (b[i] >> shift & 0xFF));
                worst = Math.max(worst, d);
                sum += d;
            }
        }
        double mean = sum / (3.0 * n);
        assertTrue(n > 50_000, n + " tile pixels inside the crop");
        assertTrue(fromImage > n * 0.95, "the image, not the etopo1 tint, is drawn: " + fromImage + " of " + n);
        assertTrue(worst <= 3, "worst channel difference " + worst);
        assertTrue(mean < 0.3, "mean channel difference " + mean);
        assertTrue(outside > 200_000, outside + " tile pixels outside the crop");
        assertEquals(outside, outsideSame, "outside the image the etopo1 tint stays");
    }


    @Test
    void theTilesOfAZoomSideBySideAreTheDrapeSampledOverTheWholeZoomAtOnce() throws Exception {
        // without light, a tile pixel is the drape over the tint: the tiles of each zoom, put side by side, are the
        // colours of the drape over the whole zoom's grid in one piece composited over the tiles without it
        Scene unlit = Scene.defaults().withHillshade(null);
        Drape drape = Drape.of(List.of(IMAGE));
        TileJob job = TileJob.of(DEM, new ZoomRange(10, 12));
        Path plain = dir.resolve("plain");
        Path draped = dir.resolve("draped");
        job.withScene(unlit).run(plain, JobListener.NONE);
        job.withScene(unlit.withDrape(drape)).run(draped, JobListener.NONE);
        for (int z = 10; z <= 12; z++) {
            TileRange range = range(z);
            GridGeometry picture = picture(range);
            int[] colours = drape.forPicture(picture).argb(picture,
                    new CellWindow(0, 0, picture.width(), picture.height()));
            int[] under = mosaic(plain, range);
            int[] got = mosaic(draped, range);
            int covered = 0;
            int seams = 0;
            int opaque = 0;
            for (int i = 0; i < got.length; i++) {
                if (under[i] >>> 24 != 255) {
                    assertEquals(under[i], got[i], "no data, or no tile, at " + i);
                    continue;
                }
                opaque++;
                assertEquals(ColorLayer.over(colours[i], under[i]), got[i], "zoom " + z + " pixel " + i);
                if (colours[i] >>> 24 != 0) {
                    covered++;
                    int c = i % picture.width();
                    int r = i / picture.width();
                    seams += c % S == 0 || c % S == S - 1 || r % S == 0 || r % S == S - 1 ? 1 : 0;
                }
            }
            assertTrue(covered > 3000, "zoom " + z + ": " + covered + " pixels under the image");
            assertTrue(seams > 0 || z == 10, "zoom " + z + ": " + seams + " of them along a tile seam");
            assertTrue(opaque > covered * 4, "zoom " + z + ": the tint around the image, " + opaque);
        }
    }

    @Test
    void anImageFourTimesFinerThanATilePixelIsReadEveryFourthPixel() throws Exception {
        // zoom 10: a tile pixel is 152.87 m of Web Mercator, 152.87 · cos 34.34° = 126.2 m on the ground at Big
        // Tujunga (UTM's scale there is within 0.1 % of 1), so 4.2 of the image's 30 m pixels: the image is read
        // every 4th pixel from the 3rd (2 + 4i) and each tile pixel takes the pixel read nearest its centre (not
        // the colours of the world's centre, where the image's UTM zone does not reach)
        int z = 10;
        double perPixel = WebMercatorTile.pixelSize(z) * Math.cos(Math.toRadians(34.34)) / 30;
        assertEquals(4, (int) Math.floor(perPixel));
        DrapeImage image = DrapeImage.open(IMAGE);
        GridGeometry g = image.grid();
        int[] px = image.readArgb(0, 0, CROP_W, CROP_H);
        int nx = (CROP_W - 3) / 4 + 1;   // columns 2, 6, … read
        int ny = (CROP_H - 3) / 4 + 1;
        Path draped = dir.resolve("draped");
        TileJob.of(DEM, new ZoomRange(z, z)).withScene(Scene.defaults().withHillshade(null)
                .withDrape(Drape.of(List.of(IMAGE)))).run(draped, JobListener.NONE);
        TileRange range = range(z);
        GridGeometry picture = picture(range);
        int[] got = mosaic(draped, range);
        double[] utm = utm(picture);
        int n = 0;
        int same = 0;
        int bilinearWouldDiffer = 0;
        for (int i = 0; i < got.length; i++) {
            // pixel-centre coordinates in the image, pixel i's centre at i
            double u = (utm[2 * i] - g.originX()) / g.cellWidth() - 0.5;
            double v = (g.originY() - utm[2 * i + 1]) / g.cellHeight() - 0.5;
            if (!(u >= 0 && u <= CROP_W - 1 && v >= 0 && v <= CROP_H - 1)) {
                continue;
            }
            double iu = (u - 2) / 4;
            double iv = (v - 2) / 4;
            if (Math.abs(iu - Math.floor(iu) - 0.5) < 1e-6 || Math.abs(iv - Math.floor(iv) - 0.5) < 1e-6) {
                continue;   // halfway between two pixels read
            }
            int ci = 2 + 4 * Math.min(Math.max((int) Math.floor(iu + 0.5), 0), nx - 1);
            int ri = 2 + 4 * Math.min(Math.max((int) Math.floor(iv + 0.5), 0), ny - 1);
            n++;
            same += got[i] == px[ri * CROP_W + ci] ? 1 : 0;
            bilinearWouldDiffer += px[(int) Math.round(v) * CROP_W + (int) Math.round(u)] != px[ri * CROP_W + ci]
                    ? 1 : 0;
        }
        assertTrue(n > 3000, n + " tile pixels on the image");
        assertEquals(n, same, "every tile pixel on the image is the pixel read nearest its centre");
        assertTrue(bilinearWouldDiffer > n / 4, "the image's own nearest pixel differs at " + bilinearWouldDiffer
                + " of them");
    }
}
