package io.github.jdem846.shade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.TestDems;
import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.file.Path;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Our HORN, MULTIDIRECTIONAL, COMBINED and IGOR gray bytes against gdaldem 3.6.2's PNGs in
 * testdata/golden/hillshade (made by make_goldens.sh there): within 1 DN everywhere, the same no-data mask, and
 * nearly all bytes exactly equal.
 */
class GdaldemGoldenTest {

    private static final Path GOLDEN = Path.of("testdata", "golden", "hillshade");
    private static final double GDAL_SCALE = 111120;

    /** A crop of a test DEM (full = whole DEM) and gdaldem's options. */
    record Case(String png, String dem, int col, int row, int w, int h, HillshadeMethod method, double az,
                double alt, double z, double scale) {
        @Override
        public String toString() {
            return png;
        }
    }

    static Stream<Arguments> cases() {
        String bt = TestDems.BIG_TUJUNGA;
        String jb = TestDems.JACKSBORO;
        String lux = TestDems.LUXEMBOURG;
        String vo = TestDems.VOLCANO;
        String va = TestDems.VANCOUVER;
        HillshadeMethod horn = HillshadeMethod.HORN;
        HillshadeMethod multi = HillshadeMethod.MULTIDIRECTIONAL;
        HillshadeMethod igor = HillshadeMethod.IGOR;
        HillshadeMethod combined = HillshadeMethod.COMBINED;
        double metric = Double.NaN;
        return Stream.of(
                new Case("bt_horn_az315_alt45", bt, 420, 120, 300, 200, horn, 315, 45, 1, metric),
                new Case("bt_horn_az100.5_alt12.3_z2", bt, 420, 120, 300, 200, horn, 100.5, 12.3, 2, metric),
                new Case("bt_horn_az200_alt70", bt, 420, 120, 300, 200, horn, 200, 70, 1, metric),
                new Case("bt_horn_az33.3_alt0.01", bt, 420, 120, 300, 200, horn, 33.3, 0.01, 1, metric),
                new Case("bt_multidir_alt45", bt, 420, 120, 300, 200, multi, 315, 45, 1, metric),
                new Case("bt_multidir_alt30_z3", bt, 420, 120, 300, 200, multi, 315, 30, 3, metric),
                new Case("jb_horn_s111120_az315_alt45", jb, 100, 80, 200, 160, horn, 315, 45, 1, GDAL_SCALE),
                new Case("jb_horn_s111120_az250_alt25_z2", jb, 100, 80, 200, 160, horn, 250, 25, 2, GDAL_SCALE),
                new Case("jb_multidir_s111120_alt60", jb, 100, 80, 200, 160, multi, 315, 60, 1, GDAL_SCALE),
                new Case("lux_horn_s111120_az315_alt45", lux, 0, 0, 95, 90, horn, 315, 45, 1, GDAL_SCALE),
                new Case("lux_horn_s111120_az57_alt5_z5", lux, 0, 0, 95, 90, horn, 57, 5, 5, GDAL_SCALE),
                new Case("lux_multidir_s111120_alt45_z5", lux, 0, 0, 95, 90, multi, 315, 45, 5, GDAL_SCALE),
                new Case("vo_horn_az135_altm5", vo, 0, 0, 61, 87, horn, 135, -5, 1, metric),
                new Case("vo_horn_az1e6_alt89.99", vo, 0, 0, 61, 87, horn, 1e6, 89.99, 1, metric),
                new Case("vo_horn_azm720_alt90", vo, 0, 0, 61, 87, horn, -720, 90, 1, metric),
                new Case("va_horn_az300_alt35_z10", va, 0, 0, 120, 91, horn, 300, 35, 10, metric),
                new Case("va_multidir_alt45_z10", va, 0, 0, 120, 91, multi, 315, 45, 10, metric),
                new Case("bt_igor_az315", bt, 420, 120, 300, 200, igor, 315, 45, 1, metric),
                new Case("bt_igor_az100_z3", bt, 420, 120, 300, 200, igor, 100, 45, 3, metric),
                new Case("bt_combined_az315_alt45", bt, 420, 120, 300, 200, combined, 315, 45, 1, metric),
                new Case("bt_combined_az100_alt20_z3", bt, 420, 120, 300, 200, combined, 100, 20, 3, metric),
                new Case("lux_igor_s111120_az315", lux, 0, 0, 95, 90, igor, 315, 45, 1, GDAL_SCALE),
                new Case("lux_combined_s111120_az57_alt5_z5", lux, 0, 0, 95, 90, combined, 57, 5, 5, GDAL_SCALE))
                .map(Arguments::of);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void matchesGdaldemWithinOneDn(Case k) throws IOException {
        Dem full = TestDems.load(k.dem());
        Dem dem = k.w() == full.width() && k.h() == full.height() ? full : full.crop(k.col(), k.row(), k.w(), k.h());
        HillshadeOptions options = HillshadeOptions.DEFAULTS.withZFactor(k.z()).withHorizontalScale(k.scale());
        float[] illum = new float[dem.width() * dem.height()];
        k.method().stage(options).illuminate(dem, new LightDirection(k.az(), k.alt()), 0, 0, dem.width(),
                dem.height(), illum);
        byte[] ours = k.method().toGray(illum, options);

        BufferedImage img = ImageIO.read(GOLDEN.resolve(k.png() + ".png").toFile());
        assertEquals(dem.width(), img.getWidth(), "golden width");
        assertEquals(dem.height(), img.getHeight(), "golden height");
        Raster raster = img.getRaster();
        int maxDiff = 0;
        int equal = 0;
        int noData = 0;
        for (int r = 0; r < dem.height(); r++) {
            for (int c = 0; c < dem.width(); c++) {
                int theirs = raster.getSample(c, r, 0);
                int mine = ours[r * dem.width() + c] & 0xFF;
                assertEquals(theirs == 0, mine == 0, "no-data mask differs at column " + c + ", row " + r);
                noData += theirs == 0 ? 1 : 0;
                maxDiff = Math.max(maxDiff, Math.abs(theirs - mine));
                equal += theirs == mine ? 1 : 0;
            }
        }
        int cells = dem.width() * dem.height();
        double fractionEqual = (double) equal / cells;
        System.out.printf("golden %-34s %7d cells, %5d no-data, max |diff| %d DN, exactly equal %.5f%n", k.png(),
                cells, noData, maxDiff, fractionEqual);
        assertTrue(maxDiff <= 1, k.png() + ": max |diff| " + maxDiff + " DN > 1");
        assertTrue(fractionEqual >= 0.999, k.png() + ": only " + fractionEqual + " of the bytes are equal");
        if (k.dem().equals(TestDems.LUXEMBOURG)) {
            assertTrue(noData > 3000, "the Luxembourg golden must exercise no-data, got " + noData);
        }
    }
}
