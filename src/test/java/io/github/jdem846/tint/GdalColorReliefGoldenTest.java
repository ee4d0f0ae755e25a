package io.github.jdem846.tint;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.TestDems;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;

/**
 * Every pixel of our tint against {@code gdaldem color-relief -alpha} (GDAL 3.6.2) on real DEMs; the golden PNGs
 * and the commands that made them are in testdata/golden/tint/.
 *
 * <p>Allowed difference: GDAL 3.6.2 rounds an interpolated channel as (int)(c + 0.45), we (and GDAL ≥ 3.9.2) as
 * (int)(c + 0.5), so ours minus gdaldem's is 0 or 1 on every channel of interpolated pixels and 0 elsewhere.
 */
class GdalColorReliefGoldenTest {

    private static final Path GOLDEN = Path.of("testdata", "golden", "tint");

    private static Dem vancouver() {
        return TestDems.load(TestDems.VANCOUVER);
    }

    private static Dem luxembourg() {
        return TestDems.load(TestDems.LUXEMBOURG);
    }

    private static Dem bigTujungaCrop() {
        return TestDems.load(TestDems.BIG_TUJUNGA).crop(420, 120, 320, 240);   // gdal_translate -srcwin 420 120 320 240
    }

    private static StopRamp file(String name, ColorSelection selection) throws IOException {
        return ColorRamp.fromGdalColorFile(GOLDEN.resolve("colors").resolve(name), selection);
    }

    @Test
    void absoluteStopsWithAlphaAndMixedSeparators() throws IOException {
        assertRoundingOnly(vancouver(), file("vancouver_absolute.txt", ColorSelection.INTERPOLATE),
                "vancouver_absolute.png");
    }

    @Test
    void percentStopsWithTransparentNoData() throws IOException {
        StopRamp table2 = file("table2_percent.txt", ColorSelection.INTERPOLATE);
        assertRoundingOnly(luxembourg(), table2, "luxembourg_table2.png");
        assertRoundingOnly(bigTujungaCrop(), table2, "bigtujunga_crop_table2.png");
    }

    @Test
    void builtInHypsometricIsTheArticlesTable2() throws IOException {
        ColorRamp hypsometric = ColorRamp.named("hypsometric");
        assertRoundingOnly(luxembourg(), hypsometric, "luxembourg_table2.png");
        assertRoundingOnly(bigTujungaCrop(), hypsometric, "bigtujunga_crop_table2.png");
    }

    @Test
    void builtInEtopo1MatchesThePublishedPalette() throws IOException {
        assertRoundingOnly(vancouver(), ColorRamp.named("etopo1"), "vancouver_etopo1.png");
        assertRoundingOnly(vancouver(), file("etopo1.txt", ColorSelection.INTERPOLATE), "vancouver_etopo1.png");
    }

    @Test
    void builtInStandardSplitsAtSeaLevel() throws IOException {
        // The golden colour file starts land at 0.0001 m instead of 0 m (a stop at exactly 0 would make a
        // duplicate that gdaldem blends), which moves interpolated land colours by < 0.001; so ±1 here.
        BufferedImage gdal = golden("vancouver_standard.png");
        Dem dem = vancouver();
        TintFunction ours = ColorRamp.named("standard").bind(dem);
        compare(dem, ours, gdal, -1, 1);
    }

    @Test
    void colourNamesAndMixedUnitsOnValidCells_noDataStaysTransparent() throws IOException {
        Dem dem = luxembourg();
        TintFunction ours = file("names_mixed.txt", ColorSelection.INTERPOLATE).bind(dem);
        BufferedImage gdal = golden("luxembourg_names.png");
        int noData = 0;
        for (int row = 0; row < dem.height(); row++) {
            for (int col = 0; col < dem.width(); col++) {
                float e = dem.get(col, row);
                int g = gdal.getRGB(col, row);
                int o = ours.argb(e);
                if (Float.isNaN(e)) {
                    // Deviation: without an 'nv' line gdaldem paints no-data (-32768) with the first stop, blue.
                    assertEquals(0xFF0000FF, g, "gdaldem at no-data " + col + "," + row);
                    assertEquals(0, o, "ours at no-data " + col + "," + row);
                    noData++;
                } else {
                    assertChannels(o, g, 0, 1, col, row, e);
                }
            }
        }
        assertEquals(3942, noData);
    }

    @Test
    void nearestEntryIncludingTies() throws IOException {
        Dem dem = bigTujungaCrop();
        TintFunction ours = file("nearest_classes.txt", ColorSelection.NEAREST).bind(dem);
        int ties = 0;
        for (int i = 0; i < dem.backingArray().length; i++) {
            if ((dem.backingArray()[i] - 875) % 250 == 0) {
                ties++;
            }
        }
        assertTrue(ties > 100, "the crop has cells exactly between two classes: " + ties);
        assertEquals(0, compare(dem, ours, golden("bigtujunga_crop_nearest.png"), 0, 0));
    }

    @Test
    void exactEntry() throws IOException {
        Dem dem = luxembourg();
        TintFunction ours = file("exact_every5m.txt", ColorSelection.EXACT).bind(dem);
        BufferedImage gdal = golden("luxembourg_exact.png");
        compare(dem, ours, gdal, 0, 0);
        int matched = 0;
        for (int row = 0; row < dem.height(); row++) {
            for (int col = 0; col < dem.width(); col++) {
                if (gdal.getRGB(col, row) != 0) {
                    matched++;
                    assertEquals(0, dem.get(col, row) % 5, "only multiples of 5 m are coloured");
                }
            }
        }
        assertTrue(matched > 500 && matched < 4608 / 2, "about a fifth of the valid cells match: " + matched);
    }

    // ---------------------------------------------------------------------------------------------------

    private static void assertRoundingOnly(Dem dem, ColorRamp ramp, String png) throws IOException {
        int interpolated = compare(dem, ramp.bind(dem), golden(png), 0, 1);
        assertTrue(interpolated > 0);
    }

    private static BufferedImage golden(String png) throws IOException {
        BufferedImage image = ImageIO.read(GOLDEN.resolve(png).toFile());
        assertNotEquals(null, image, png);
        return image;
    }

    /**
     * Asserts ours − gdaldem ∈ [lo, hi] on every channel of every pixel; returns the number of pixels that differ
     * by anything.
     */
    private static int compare(Dem dem, TintFunction ours, BufferedImage gdal, int lo, int hi) {
        assertEquals(dem.width(), gdal.getWidth());
        assertEquals(dem.height(), gdal.getHeight());
        int differing = 0;
        for (int row = 0; row < dem.height(); row++) {
            for (int col = 0; col < dem.width(); col++) {
                float e = dem.get(col, row);
                int o = ours.argb(e);
                int g = gdal.getRGB(col, row);
                assertChannels(o, g, lo, hi, col, row, e);
                if (o != g) {
                    differing++;
                }
            }
        }
        return differing;
    }

    private static void assertChannels(int ours, int gdal, int lo, int hi, int col, int row, float e) {
        for (int shift = 0; shift < 32; shift += 8) {
            int d = (ours >>> shift & 0xFF) - (gdal >>> shift & 0xFF);
            if (d < lo || d > hi) {
                throw new AssertionError(String.format("pixel %d,%d (elevation %s): ours %08X, gdaldem %08X", col,
                        row, e, ours, gdal));
            }
        }
    }
}
