package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.shadow.CellWindow;
import io.github.jdem846.shadow.FileWindowCase;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowOptions;
import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code jdem846 shadows} and {@code render --shadows} end to end, in-process, on real and hand-made DEMs. */
class ShadowsCommandTest {

    private static final String LUX = "testdata/dem/luxembourg_srtm30s_wgs84.tif";
    private static final String JACKSBORO = "testdata/dem/jacksboro_srtm3s_wgs84.tif";
    private static final String VOLCANO = "testdata/dem/maungawhau-volcano_10m_nztm-approx.tif";

    @TempDir
    Path dir;

    /** Runs {@code shadows FILE -o OUT.png ARGS…}, asserts success and returns the mask's samples (row-major). */
    private int[] mask(String dem, String name, String... args) throws IOException {
        Path out = dir.resolve(name);
        String[] all = Stream.concat(Stream.of("shadows", dem, "-o", out.toString(), "-q"), Stream.of(args))
                .toArray(String[]::new);
        CliRun run = CliRun.of(all);
        assertEquals(0, run.exitCode(), run.err());
        BufferedImage img = ImageIO.read(out.toFile());
        assertEquals(1, img.getRaster().getNumBands(), "a gray mask");
        Raster r = img.getRaster();
        return r.getSamples(0, 0, r.getWidth(), r.getHeight(), 0, (int[]) null);
    }

    private static long count(int[] mask, int value) {
        return java.util.Arrays.stream(mask).filter(v -> v == value).count();
    }

    @Test
    void anyAzimuthParsesAndIsReducedToAFullTurn() throws IOException {
        int[] minus720 = mask(LUX, "a.png", "--sun-azimuth=-720", "--sun-elevation", "3");
        int[] zero = mask(LUX, "b.png", "--sun-azimuth", "0", "--sun-elevation", "3");
        int[] huge = mask(LUX, "c.png", "--sun-azimuth", "1000000", "--sun-elevation", "3");   // ≡ 280°
        int[] west = mask(LUX, "d.png", "--sun-azimuth", "280", "--sun-elevation", "3");
        assertArrayEquals(zero, minus720);
        assertArrayEquals(west, huge);
        assertTrue(count(zero, 255) > 0 && count(west, 255) > 0, "a 3° sun casts shadows in Luxembourg");
    }

    @Test
    void theMaskIsBinaryTheSizeOfTheDemAndNoDataIsZero() throws IOException {
        Dem lux = DemReader.read(Path.of(LUX));
        for (String algorithm : new String[] {"sweep", "march", "exact"}) {
            Path out = dir.resolve(algorithm + ".png");
            CliRun run = CliRun.of("shadows", LUX, "-o", out.toString(), "-q", "--algorithm", algorithm,
                    "--sun-azimuth", "250", "--sun-elevation", "4");
            assertEquals(0, run.exitCode(), run.err());
            BufferedImage img = ImageIO.read(out.toFile());
            assertEquals(lux.width(), img.getWidth(), algorithm);
            assertEquals(lux.height(), img.getHeight(), algorithm);
            int noData = 0;
            for (int y = 0; y < img.getHeight(); y++) {
                for (int x = 0; x < img.getWidth(); x++) {
                    int v = img.getRaster().getSample(x, y, 0);
                    assertTrue(v == 0 || v == 255, algorithm + ": hard mask value " + v);
                    if (!lux.isValid(x, y)) {
                        assertEquals(0, v, algorithm + ": no-data cell " + x + "," + y);
                        noData++;
                    }
                }
            }
            assertEquals(3942, noData, "Luxembourg's no-data border");
        }
    }

    @Test
    void rowZeroIsNorthAndAGeoTiffMaskIsWrittenToo() throws IOException {
        // a hand-made ESRI ASCII grid, 20×20 cells of 30 m, flat at 0 with a 315 m east–west wall on row 5; the sun
        // in the north at 45° shades the rows whose distance 30·k m is below 315 m (rows 6–15), nothing north of it
        StringBuilder asc = new StringBuilder("ncols 20\nnrows 20\nxllcorner 0\nyllcorner 0\ncellsize 30\n"
                + "NODATA_value -9999\n");
        for (int r = 0; r < 20; r++) {
            for (int c = 0; c < 20; c++) {
                asc.append(r == 5 ? "315 " : "0 ");
            }
            asc.append('\n');
        }
        Path dem = dir.resolve("wall.asc");
        Files.writeString(dem, asc);
        for (String ext : new String[] {"png", "tif"}) {
            Path out = dir.resolve("wall." + ext);
            CliRun run = CliRun.of("shadows", dem.toString(), "-o", out.toString(), "-q", "--algorithm", "march",
                    "--sun-azimuth", "0", "--sun-elevation", "45");
            assertEquals(0, run.exitCode(), run.err());
            Raster img = ImageIO.read(out.toFile()).getRaster();
            for (int y = 0; y < 20; y++) {
                int expected = y >= 6 && y <= 15 ? 255 : 0;
                for (int x = 0; x < 20; x++) {
                    assertEquals(expected, img.getSample(x, y, 0), ext + " (" + x + ", " + y + ")");
                }
            }
        }
    }

    @Test
    void aWindowedMaskEqualsTheSameWindowOfTheWholeMask() throws IOException {
        // --window reads only the window and the upstream halo from the file (ShadowHaloSource) and traces that
        // smaller grid. Its geometry remembers where it lies in the file (GridGeometry.placement), so the sweep lays
        // its sun-parallel lines and both take their ray direction as on the whole grid: the same cells, exactly,
        // on a projected and on a lat/lon grid, hard and soft.
        String[][] cases = {
            {"testdata/dem/bigtujunga_srtm30m_utm11n.tif", "1197", "cells:700,300,150,100", "700", "300", "150", "100"},
            {JACKSBORO, "403", "cells:120,90,110,80", "120", "90", "110", "80"},
        };
        for (String[] k : cases) {
            int width = Integer.parseInt(k[1]);
            int col = Integer.parseInt(k[3]);
            int row = Integer.parseInt(k[4]);
            int w = Integer.parseInt(k[5]);
            int h = Integer.parseInt(k[6]);
            for (String algorithm : new String[] {"march", "sweep"}) {
                for (boolean soft : new boolean[] {false, true}) {
                    String[] sun = {"--algorithm", algorithm, "--sun-azimuth", "230", "--sun-elevation", "7"};
                    if (soft) {
                        sun = concat(sun, new String[] {"--soft-shadows"});
                    }
                    int[] whole = mask(k[0], algorithm + soft + "whole.png", sun);
                    int[] part = mask(k[0], algorithm + soft + "part.png",
                            concat(new String[] {"--window", k[2]}, sun));
                    assertEquals(w * h, part.length);
                    int differ = 0;
                    for (int y = 0; y < h; y++) {
                        for (int x = 0; x < w; x++) {
                            differ += whole[(row + y) * width + col + x] != part[y * w + x] ? 1 : 0;
                        }
                    }
                    assertEquals(0, differ, k[0] + " " + algorithm + " soft=" + soft + ": cells that differ");
                }
            }
        }
    }

    /**
     * A case where the window's grid alone has a smaller elevation range than the file, and where that changes the
     * sweep (found by {@link FileWindowCase#sensitive}): {@code shadows} and {@code render} must still give the
     * whole file's cells, because they hand the sweep the file's minimum.
     */
    @Test
    void aWindowedSweepEqualsTheWholeFileWhereTheWindowAloneWouldNot() throws IOException {
        FileWindowCase c;
        java.util.concurrent.ForkJoinPool pool = new java.util.concurrent.ForkJoinPool(1);
        try {
            c = FileWindowCase.sensitive(7, 400, pool);
        } finally {
            pool.shutdownNow();
        }
        Path flt = writeGridFloat(c.dem(), "probe");
        CellWindow win = c.window();
        String[] sun = {"--sun-azimuth", Double.toString(c.light().azimuthDegrees()), "--sun-elevation",
            Double.toString(c.light().elevationDegrees())};
        String cells = "cells:" + win.col() + "," + win.row() + "," + win.width() + "," + win.height();
        int[] whole = mask(flt.toString(), "whole.png", concat(new String[] {"--algorithm", "sweep"}, sun));
        int[] part = mask(flt.toString(), "part.png",
                concat(new String[] {"--algorithm", "sweep", "--window", cells}, sun));
        int[] wholeRgb = rgb(flt, "whole-render.png", sun);
        int[] partRgb = rgb(flt, "part-render.png", concat(new String[] {"--window", cells}, sun));
        int width = c.dem().width();
        int differ = 0;
        int differRgb = 0;
        for (int y = 0; y < win.height(); y++) {
            for (int x = 0; x < win.width(); x++) {
                int at = (win.row() + y) * width + win.col() + x;
                differ += whole[at] != part[y * win.width() + x] ? 1 : 0;
                differRgb += wholeRgb[at] != partRgb[y * win.width() + x] ? 1 : 0;
            }
        }
        assertEquals(0, differ, "shadows " + c.light() + " " + cells + ": cells that differ");
        assertEquals(0, differRgb, "render " + c.light() + " " + cells + ": pixels that differ");
    }

    /** {@code render --tint gray --hillshade none --shadows sweep} of {@code flt}: the ARGB pixels. */
    private int[] rgb(Path flt, String name, String... args) throws IOException {
        Path out = dir.resolve(name);
        CliRun run = CliRun.of(concat(new String[] {"render", flt.toString(), "-o", out.toString(), "-q", "--tint",
            "gray", "--hillshade", "none", "--shadows", "sweep"}, args));
        assertEquals(0, run.exitCode(), run.err());
        BufferedImage img = ImageIO.read(out.toFile());
        return img.getRGB(0, 0, img.getWidth(), img.getHeight(), null, 0, img.getWidth());
    }

    /** Writes {@code dem} (a metric grid) as GridFloat in UTM zone 11N, no-data −9999. */
    private Path writeGridFloat(Dem dem, String name) throws IOException {
        float[] v = dem.backingArray();
        java.nio.ByteBuffer buf = java.nio.ByteBuffer.allocate(4 * v.length).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        for (float z : v) {
            buf.putFloat(z == z ? z : -9999f);
        }
        Path flt = dir.resolve(name + ".flt");
        Files.write(flt, buf.array());
        Files.writeString(dir.resolve(name + ".hdr"), String.format(Locale.ROOT, "ncols %d%nnrows %d%n"
                + "xllcorner 400000%nyllcorner 3700000%ncellsize %s%nNODATA_value -9999%nbyteorder LSBFIRST%n",
                dem.width(), dem.height(), Double.toString(dem.geometry().cellWidth())));
        Files.copy(Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.prj"), dir.resolve(name + ".prj"));
        return flt;
    }

    @Test
    void softShadowsGiveIntermediateValuesAroundTheHardShadows() throws IOException {
        int[] hard = mask(JACKSBORO, "hard.png", "--sun-azimuth", "300", "--sun-elevation", "6");
        int[] soft = mask(JACKSBORO, "soft.png", "--sun-azimuth", "300", "--sun-elevation", "6", "--soft-shadows");
        long between = java.util.Arrays.stream(soft).filter(v -> v > 0 && v < 255).count();
        assertTrue(between > 0.01 * soft.length, "penumbra cells: " + between + " of " + soft.length);
        assertTrue(count(hard, 255) > 0.05 * hard.length, "a 6° sun shades Pine Mountain's north-west slopes");
        // the hard test asks whether the horizon is above the disk's centre, i.e. whether more than half of the
        // disk is hidden: hard = 255 exactly where soft > 127.5 (bytes 127 and 128 left out for rounding)
        for (int i = 0; i < soft.length; i++) {
            if (soft[i] != 127 && soft[i] != 128) {
                assertEquals(soft[i] > 127 ? 255 : 0, hard[i], "cell " + i + ": soft " + soft[i]);
            }
        }
    }

    @Test
    void thinFeaturesOnlyAddTheLibrarysOwnRayShadows() throws IOException {
        // --thin-features is the library's ShadowOptions.withThinFeatures(true): the mask equals it byte for byte,
        // and it only adds shadow to the plain sweep (one more sample of each cell's own ray)
        int[] plain = mask(JACKSBORO, "plain.png", "--sun-azimuth", "250", "--sun-elevation", "8");
        int[] thin = mask(JACKSBORO, "thin.png", "--sun-azimuth", "250", "--sun-elevation", "8", "--thin-features");
        Dem dem = DemReader.read(Path.of(JACKSBORO));
        float[] lib = ShadowAlgorithm.SWEEP.compute(dem, new LightDirection(250, 8),
                ShadowOptions.DEFAULTS.withThinFeatures(true), new java.util.concurrent.ForkJoinPool(2))
                .backingArray();
        long added = 0;
        for (int i = 0; i < thin.length; i++) {
            assertEquals(lib[i] > 0.5f ? 255 : 0, thin[i], "cell " + i);
            assertTrue(thin[i] >= plain[i], "cell " + i + " lost shadow");
            added += thin[i] > plain[i] ? 1 : 0;
        }
        assertTrue(added > 0, "some cell of Pine Mountain's ridges must gain shadow");
    }

    @Test
    void thinFeaturesWithAnotherAlgorithmIsNotedAndChangesNothing() throws IOException {
        Path a = dir.resolve("march.png");
        Path b = dir.resolve("march-thin.png");
        CliRun plain = CliRun.of("shadows", LUX, "-o", a.toString(), "--algorithm", "march", "-q");
        CliRun thin = CliRun.of("shadows", LUX, "-o", b.toString(), "--algorithm", "march", "--thin-features", "-q");
        assertEquals(0, thin.exitCode(), thin.err());
        assertTrue(thin.err().contains("--thin-features changes only the sweep"), thin.err());
        assertFalse(plain.err().contains("--thin-features"), plain.err());
        assertArrayEquals(Files.readAllBytes(a), Files.readAllBytes(b));
        CliRun render = CliRun.of("render", LUX, "-o", dir.resolve("r.png").toString(), "--thin-features", "-q");
        assertEquals(0, render.exitCode(), render.err());
        assertTrue(render.err().contains("no effect with no shadows"), render.err());
    }

    @Test
    void curvatureOnlyLowersDistantTerrain() throws IOException {
        // Luxembourg, 30″ cells, ≈ 55 × 83 km; a 1° sun casts shadows over tens of kilometres, where the
        // curvature less refraction, 0.87·d²/(2R), is ≈ 27 m at 20 km: some shadows end sooner, none appear
        int[] flat = mask(LUX, "flat.png", "--sun-azimuth", "250", "--sun-elevation", "1");
        int[] round = mask(LUX, "round.png", "--sun-azimuth", "250", "--sun-elevation", "1", "--curvature");
        long lost = 0;
        for (int i = 0; i < flat.length; i++) {
            assertFalse(round[i] == 255 && flat[i] == 0, "cell " + i + " gained shadow from the Earth's curvature");
            lost += flat[i] == 255 && round[i] == 0 ? 1 : 0;
        }
        assertTrue(lost > 0, "some cells must be lit once the curvature lowers the far terrain");
    }

    @Test
    void renderWithShadowsDarkensExactlyTheShadowCells() throws IOException {
        String[] sun = {"--sun-azimuth", "250", "--sun-elevation", "10"};
        int[] mask = mask(VOLCANO, "mask.png", concat(new String[] {"--algorithm", "sweep"}, sun));
        Path plain = dir.resolve("plain.png");
        Path shaded = dir.resolve("shaded.png");
        assertEquals(0, CliRun.of(concat(new String[] {"render", VOLCANO, "-o", plain.toString(), "-q"}, sun))
                .exitCode());
        assertEquals(0, CliRun.of(concat(new String[] {"render", VOLCANO, "-o", shaded.toString(), "-q",
            "--shadows", "sweep"}, sun)).exitCode());
        BufferedImage a = ImageIO.read(plain.toFile());
        BufferedImage b = ImageIO.read(shaded.toFile());
        int w = a.getWidth();
        long darkened = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < w; x++) {
                int pa = a.getRGB(x, y);
                int pb = b.getRGB(x, y);
                boolean inShadow = mask[y * w + x] == 255;
                String at = String.format(Locale.ROOT, "(%d, %d) %08x → %08x", x, y, pa, pb);
                if (!inShadow) {
                    assertEquals(pa, pb, "lit cell changed " + at);
                    continue;
                }
                assertEquals(pa >>> 24, pb >>> 24, "alpha kept " + at);
                assertTrue(lum(pb) <= lum(pa), "shadow never brightens " + at);
                darkened += lum(pb) < lum(pa) ? 1 : 0;
            }
        }
        long shadowCells = count(mask, 255);
        assertTrue(shadowCells > 50, "the volcano casts shadows at 10°: " + shadowCells);
        assertEquals(shadowCells, darkened, "every shadow cell is darker");
    }

    private static int lum(int argb) {
        return ((argb >> 16) & 0xff) + ((argb >> 8) & 0xff) + (argb & 0xff);
    }

    @Test
    void anglesThatAreNotNumbersOrOutOfRangeAreBadUsageWithoutAnOutputFile() {
        // NaN, Infinity and an elevation out of [-90, 90] are refused while parsing, like "abc": exit 2 naming the
        // option and the value. No output file in any case.
        String[][] bad = {
            {"--sun-azimuth", "NaN"}, {"--sun-azimuth", "abc"}, {"--sun-azimuth", "Infinity"},
            {"--sun-elevation", "NaN"}, {"--sun-elevation", "abc"}, {"--sun-elevation", "-Infinity"},
            {"--sun-elevation", "91"},
        };
        for (String[] args : bad) {
            for (String command : new String[] {"shadows", "render"}) {
                Path out = dir.resolve(command + ".png");
                CliRun run = CliRun.of(concat(new String[] {command, VOLCANO, "-o", out.toString(), "-q"}, args));
                String what = command + " " + String.join(" ", args);
                assertEquals(2, run.exitCode(), what + ": " + run.err());
                assertTrue(run.err().contains(args[0]) && run.err().contains(args[1]),
                        what + " names the option and the value: " + run.err());
                assertFalse(run.err().contains("\tat "), what + ": no stack trace");
                assertFalse(Files.exists(out), what + ": no output file");
            }
        }
    }

    private static String[] concat(String[] a, String[] b) {
        return Stream.concat(Stream.of(a), Stream.of(b)).toArray(String[]::new);
    }
}
