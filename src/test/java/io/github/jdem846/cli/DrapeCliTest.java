package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code render --drape}: against pictures made by GDAL (testdata/golden/drape, see its README): gdaldem's
 * colour relief of a crop of Big Tujunga with our default tint's stops in metres, on the DEM's grid and warped to
 * latitude/longitude; hand-worked alpha compositing; the light on a drape as on a tint; windows and tiles.
 */
class DrapeCliTest {

    private static final String DEM = "testdata/dem/bigtujunga_srtm30m_utm11n.tif";
    private static final String GOLDEN = "testdata/golden/drape/";
    /** The crop the golden images cover: gdal_translate -srcwin 420 120 320 240. */
    private static final String CROP = "cells:420,120,320,240";
    /** Big Tujunga's grid: the north-west corner and the cell size. */
    private static final double WEST = 376313.6554542635;
    private static final double NORTH = 3807917.8276283755;

    @TempDir
    Path dir;

    private static CliRun run(String... args) {
        String[] all = Arrays.copyOf(args, args.length + 3);
        all[args.length] = "-q";
        all[args.length + 1] = "--threads";
        all[args.length + 2] = "2";
        CliRun r = CliRun.of(all);
        assertEquals(0, r.exitCode(), String.join(" ", args) + ": " + r.err());
        return r;
    }

    private static BufferedImage read(Path png) throws IOException {
        return ImageIO.read(png.toFile());
    }

    @Test
    void gdaldemsColourReliefDrapedWithoutLightIsItsOwnPixelsAndOurTintWithinOneLevel() throws IOException {
        Path tint = dir.resolve("tint.png");
        Path etopo = dir.resolve("etopo.png");
        Path tif = dir.resolve("drape-tif.png");
        Path png = dir.resolve("drape-png.png");
        run("tint", DEM, "--window", CROP, "-o", tint.toString());
        run("tint", DEM, "--window", CROP, "--tint", "etopo1", "-o", etopo.toString());
        // the drape replaces another tint (etopo1) entirely
        run("render", DEM, "--window", CROP, "--tint", "etopo1", "--hillshade", "none", "--drape",
                GOLDEN + "bigtujunga_crop_table2_utm.tif", "-o", tif.toString());
        // the same picture as a PNG placed by its .wld, its CRS from GDAL's .aux.xml
        run("render", DEM, "--window", CROP, "--tint", "etopo1", "--hillshade", "none", "--drape",
                GOLDEN + "bigtujunga_crop_table2_utm.png", "-o", png.toString());
        BufferedImage gdal = read(Path.of(GOLDEN + "bigtujunga_crop_table2_utm.png"));
        BufferedImage ours = read(tint);
        BufferedImage other = read(etopo);
        BufferedImage draped = read(tif);
        BufferedImage drapedPng = read(png);
        assertEquals(320, draped.getWidth());
        int worst = 0;
        int differentFromEtopo = 0;
        for (int y = 0; y < 240; y++) {
            for (int x = 0; x < 320; x++) {
                int d = draped.getRGB(x, y);
                assertEquals(gdal.getRGB(x, y), d, "the image's own pixel at " + x + "," + y);
                assertEquals(d, drapedPng.getRGB(x, y), "PNG + world file as GeoTIFF at " + x + "," + y);
                worst = Math.max(worst, maxChannelDifference(d, ours.getRGB(x, y)));
                differentFromEtopo += maxChannelDifference(d, other.getRGB(x, y)) > 8 ? 1 : 0;
            }
        }
        // gdaldem 3.6.2 rounds interpolated channels with +0.45, ours with +0.5 (docs/tint.md)
        assertTrue(worst <= 1, "our tint and gdaldem's relief differ by " + worst);
        assertTrue(differentFromEtopo > 320 * 240 / 2, "the drape, not the etopo1 tint, is drawn: "
                + differentFromEtopo);
    }

    @Test
    void theSamePictureWarpedToLatitudeLongitudeGivesNearlyTheSameColours() throws IOException {
        Path tint = dir.resolve("tint.png");
        Path draped = dir.resolve("draped.png");
        run("tint", DEM, "--window", CROP, "-o", tint.toString());
        run("render", DEM, "--window", CROP, "--tint", "etopo1", "--hillshade", "none", "--drape",
                GOLDEN + "bigtujunga_crop_table2_wgs84.tif", "-o", draped.toString());
        BufferedImage ours = read(tint);
        BufferedImage d = read(draped);
        int worst = 0;
        long sum = 0;
        int n = 0;
        // two cells in from the crop's edges: there gdalwarp's alpha fades the picture out over the etopo1 tint
        for (int y = 2; y < 238; y++) {
            for (int x = 2; x < 318; x++) {
                int diff = maxChannelDifference(ours.getRGB(x, y), d.getRGB(x, y));
                worst = Math.max(worst, diff);
                sum += diff;
                n++;
            }
        }
        // resampled twice (gdalwarp bilinear to 4326, ours bilinear back): measured max 3, mean 0.36
        assertTrue(worst <= 4, "worst channel difference " + worst);
        assertTrue(sum / (double) n < 0.6, "mean channel difference " + sum / (double) n);
    }

    @Test
    void outsideTheImageTheTintStays() throws IOException {
        Path tint = dir.resolve("tint.png");
        Path draped = dir.resolve("draped.png");
        run("tint", DEM, "--tint", "etopo1", "-o", tint.toString());
        run("render", DEM, "--tint", "etopo1", "--hillshade", "none", "--drape",
                GOLDEN + "bigtujunga_crop_table2_wgs84.tif", "-o", draped.toString());
        BufferedImage t = read(tint);
        BufferedImage d = read(draped);
        int changed = 0;
        for (int y = 0; y < t.getHeight(); y++) {
            for (int x = 0; x < t.getWidth(); x++) {
                boolean nearCrop = x >= 418 && x < 742 && y >= 118 && y < 362;
                if (!nearCrop) {
                    assertEquals(t.getRGB(x, y), d.getRGB(x, y), "outside the image at " + x + "," + y);
                } else if (t.getRGB(x, y) != d.getRGB(x, y)) {
                    changed++;
                }
            }
        }
        assertTrue(changed > 320 * 240 * 9 / 10, "inside, the image is drawn: " + changed);
    }

    /** A PNG of one colour covering Big Tujunga, with a world file and no .prj (so: in the DEM's CRS). */
    private Path solidImage(String name, int argb) throws IOException {
        BufferedImage img = new BufferedImage(40, 20, BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < 20; y++) {
            for (int x = 0; x < 40; x++) {
                img.setRGB(x, y, argb);
            }
        }
        Path png = dir.resolve(name + ".png");
        ImageIO.write(img, "png", png.toFile());
        double pixel = 1197 * 30.0 / 40;  // 40 × 20 pixels over the 1197 × 643 cells of 30 m
        double pixelH = 643 * 30.0 / 20;
        Files.writeString(dir.resolve(name + ".pgw"), pixel + "\n0\n0\n" + -pixelH + "\n" + (WEST + pixel / 2)
                + "\n" + (NORTH - pixelH / 2) + "\n");
        return png;
    }

    @Test
    void aHalfTransparentImageIsCompositedOverTheTint() throws IOException {
        Path png = solidImage("half", 0x802060C0);
        Path tint = dir.resolve("tint.png");
        Path draped = dir.resolve("draped.png");
        run("tint", DEM, "-o", tint.toString());
        run("render", DEM, "--hillshade", "none", "--drape", png.toString(), "-o", draped.toString());
        BufferedImage t = read(tint);
        BufferedImage d = read(draped);
        int[] over = {0x20, 0x60, 0xC0};
        for (int y = 0; y < t.getHeight(); y += 7) {
            for (int x = 0; x < t.getWidth(); x += 5) {
                int under = t.getRGB(x, y);
                int got = d.getRGB(x, y);
                assertEquals(0xFF, got >>> 24);
                for (int ch = 0; ch < 3; ch++) {
                    int shift = 16 - 8 * ch;
                    // source over an opaque tint: (α·over + (255 − α)·under) / 255, α = 128
                    long expected = Math.round((128.0 * over[ch] + 127.0 * (under >> shift & 0xFF)) / 255);
                    assertEquals(expected, got >> shift & 0xFF, "channel " + ch + " at " + x + "," + y);
                }
            }
        }
    }

    @Test
    void theLightFallsOnADrapeAsOnTheTint() throws IOException {
        // plain mid-gray (--tint none) and an opaque mid-gray image over the default tint: the same picture
        Path gray = solidImage("gray", 0xFF808080);
        Path a = dir.resolve("a.tif");
        Path b = dir.resolve("b.tif");
        String[] light = {"--shadows", "sweep", "--sun-elevation", "12", "--light-model", "sky"};
        run(concat(new String[] {"render", DEM, "--tint", "none", "-o", a.toString()}, light));
        run(concat(new String[] {"render", DEM, "--drape", gray.toString(), "-o", b.toString()}, light));
        assertArrayEquals(Files.readAllBytes(a), Files.readAllBytes(b));
    }

    @Test
    void aWindowAndTilesGetTheColoursOfTheWholePicture() throws IOException {
        Path whole = dir.resolve("whole.tif");
        Path tiled = dir.resolve("tiled.tif");
        Path wholePng = dir.resolve("whole.png");
        Path window = dir.resolve("window.png");
        String drape = GOLDEN + "bigtujunga_crop_table2_wgs84.tif";
        String[] common = {"render", DEM, "--drape", drape, "--shadows", "sweep", "--width", "900"};
        run(concat(common, "-o", whole.toString()));
        CliRun t = run(concat(common, "-o", tiled.toString(), "--memory", "300k"));
        assertArrayEquals(Files.readAllBytes(whole), Files.readAllBytes(tiled));
        run("render", DEM, "--drape", drape, "-o", wholePng.toString());
        run("render", DEM, "--drape", drape, "--window", "cells:500,200,200,100", "-o", window.toString());
        BufferedImage w = read(wholePng);
        BufferedImage part = read(window);
        for (int y = 0; y < 100; y++) {
            for (int x = 0; x < 200; x++) {
                assertEquals(w.getRGB(x + 500, y + 200), part.getRGB(x, y), "pixel " + x + "," + y);
            }
        }
        assertTrue(t.err().contains("tiles"), "rendered in tiles: " + t.err());
    }

    @Test
    void tilesTakeTheDrapeAsTheirJobDoes() throws Exception {
        Path cli = dir.resolve("cli.pmtiles");
        Path api = dir.resolve("api.pmtiles");
        Path drape = Path.of(GOLDEN + "bigtujunga_crop_table2_wgs84.tif");
        run("tiles", DEM, "--zoom", "11", "--tint", "etopo1", "--drape", drape.toString(), "-o", cli.toString());
        io.github.jdem846.tiles.TileJob.of(Path.of(DEM), new io.github.jdem846.tiles.ZoomRange(11, 11))
                .withScene(io.github.jdem846.render.Scene.defaults()
                        .withTint(io.github.jdem846.tint.ColorRamp.named("etopo1"))
                        .withDrape(io.github.jdem846.drape.Drape.of(java.util.List.of(drape))))
                .run(api, io.github.jdem846.job.JobListener.NONE);
        Path plain = dir.resolve("plain.pmtiles");
        run("tiles", DEM, "--zoom", "11", "--tint", "etopo1", "-o", plain.toString());
        assertArrayEquals(Files.readAllBytes(api), Files.readAllBytes(cli));
        assertTrue(!Arrays.equals(Files.readAllBytes(plain), Files.readAllBytes(cli)), "the drape is drawn");
    }

    @Test
    void anImageFourTimesFinerIsReadEveryFourthPixelTheSameFromGeoTiffAndPng() throws IOException {
        // our own relief at 4 × the DEM's resolution (a smooth surface: neighbouring pixels differ), as an RGBA
        // GeoTIFF and as a PNG with .pgw and .prj; Jacksboro is latitude/longitude, so are both images
        String jacksboro = "testdata/dem/jacksboro_srtm3s_wgs84.tif";
        String window = "cells:100,100,60,40";
        Path fineTif = dir.resolve("fine.tif");
        Path finePng = dir.resolve("fine.png");
        run("render", jacksboro, "--window", window, "--scale", "4", "-o", fineTif.toString());
        run("render", jacksboro, "--window", window, "--scale", "4", "--world-file", "-o", finePng.toString());
        Path a = dir.resolve("a.png");
        Path b = dir.resolve("b.png");
        run("render", jacksboro, "--window", window, "--hillshade", "none", "--drape", fineTif.toString(), "-o",
                a.toString());
        run("render", jacksboro, "--window", window, "--hillshade", "none", "--drape", finePng.toString(), "-o",
                b.toString());
        BufferedImage fine = read(finePng);
        BufferedImage fromTif = read(a);
        BufferedImage fromPng = read(b);
        assertEquals(240, fine.getWidth());
        for (int y = 0; y < 40; y++) {
            for (int x = 0; x < 60; x++) {
                // cell (x, y) spans pixels 4x..4x+3: the one read is the block's third, 4x + 2, nearest the centre
                assertEquals(fine.getRGB(4 * x + 2, 4 * y + 2), fromTif.getRGB(x, y), "GeoTIFF at " + x + "," + y);
                assertEquals(fromTif.getRGB(x, y), fromPng.getRGB(x, y), "PNG at " + x + "," + y);
            }
        }
    }

    @Test
    void theThreeDimensionalViewIsTexturedWithTheDrape() throws IOException {
        Path plain = dir.resolve("plain.png");
        Path draped = dir.resolve("draped.png");
        Path blue = solidImage("blue", 0xFF0000FF);
        String[] common = {"view", DEM, "--width", "240", "--height", "160", "--camera-elevation", "90"};
        run(concat(common, "-o", plain.toString()));
        run(concat(common, "-o", draped.toString(), "--drape", blue.toString()));
        BufferedImage p = read(plain);
        BufferedImage d = read(draped);
        // seen from straight above, the middle of the picture is terrain: blue lit by eq. 8 (which moves red, green
        // and blue alike, so red stays equal to green), where the tint (table 2: greens, browns, grays) was not
        int c = d.getRGB(120, 80);
        int t = p.getRGB(120, 80);
        assertTrue((c & 0xFF) > (c >> 16 & 0xFF) + 100 && (c >> 16 & 0xFF) == (c >> 8 & 0xFF),
                Integer.toHexString(c));
        assertTrue((t & 0xFF) < (t >> 16 & 0xFF) + 100, Integer.toHexString(t));
    }

    private static int maxChannelDifference(int p, int q) {
        int worst = 0;
        for (int shift = 0; shift <= 24; shift += 8) {
            worst = Math.max(worst, Math.abs((p >> shift & 0xFF) - (q >> shift & 0xFF)));
        }
        return worst;
    }

    private static String[] concat(String[] a, String... b) {
        String[] out = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }
}
