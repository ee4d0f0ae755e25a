package io.github.jdem846.io;

import static io.github.jdem846.io.DemAssertions.assertSameGeotransform;
import static io.github.jdem846.io.DemAssertions.assertSameValues;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.PixelAnchor;
import io.github.jdem846.testing.TestDems;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every file of testdata/variants decodes to the values it was made from (testdata/PROVENANCE.md, "Variants"),
 * compared with the independent GridFloat loader of {@link TestDems}.
 */
class VariantDecodingTest {

    private static final Path VARIANTS = Path.of("testdata", "variants");

    static List<Path> bigTujungaVariants() throws IOException {
        try (Stream<Path> s = Files.list(VARIANTS)) {
            return s.filter(p -> p.getFileName().toString().startsWith("bigtujunga_crop600x400_")).sorted().toList();
        }
    }

    static List<Path> luxembourgVariants() throws IOException {
        try (Stream<Path> s = Files.list(VARIANTS)) {
            return s.filter(p -> p.getFileName().toString().startsWith("luxembourg_"))
                    .filter(p -> p.toString().endsWith(".tif") || p.toString().endsWith(".flt")).sorted().toList();
        }
    }

    @Test
    void theVariantMatrixIsComplete() throws IOException {
        assertEquals(13, bigTujungaVariants().size(), "Big Tujunga variants v01–v13");
        assertEquals(5, luxembourgVariants().size(), "Luxembourg n01–n03, g01, g02");
    }

    @ParameterizedTest
    @MethodSource("bigTujungaVariants")
    void bigTujungaVariantEqualsTheCropItWasMadeFrom(Path file) throws IOException {
        Dem expected = TestDems.load(TestDems.BIG_TUJUNGA).crop(420, 120, 600, 400);
        LoadedDem loaded = DemReader.load(file, ReadRequest.FULL);
        assertSameValues(expected, loaded.dem(), file.toString());
        assertSameGeotransform(expected.geometry(), loaded.dem().geometry(), 1e-12, file.toString());
        assertEquals(388913.655454, loaded.dem().geometry().originX(), 1e-6, "PROVENANCE's upper-left x");
        assertEquals(3804317.827628, loaded.dem().geometry().originY(), 1e-6, "PROVENANCE's upper-left y");
        CrsInfo crs = loaded.dem().geometry().crs();
        assertEquals(32611, crs.epsg());
        assertEquals(CrsInfo.Kind.PROJECTED, crs.kind());
        assertEquals(0, loaded.dem().statistics().noDataCount());
        assertEquals(614, loaded.dem().statistics().min());
        assertEquals(2095, loaded.dem().statistics().max());
        boolean v12 = file.getFileName().toString().contains("nodata32767");
        assertEquals(v12 ? Double.valueOf(32767) : null, loaded.info().declaredNoData(), "only v12 declares NoData");
    }

    @ParameterizedTest
    @MethodSource("luxembourgVariants")
    void luxembourgVariantKeepsTheNoDataCellsAndValues(Path file) throws IOException {
        Dem expected = TestDems.load(TestDems.LUXEMBOURG);
        Dem actual = DemReader.read(file);
        assertEquals(3942, DemAssertions.noDataCount(actual));
        assertEquals(3942, actual.statistics().noDataCount());
        assertSameValues(expected, actual, file.toString());
        assertSameGeotransform(expected.geometry(), actual.geometry(), 1e-9, file.toString());
        assertTrue(actual.geometry().crs().isGeographic(), "EPSG:4326 / GCS_WGS_1984");
    }

    @Test
    void xllcenterGivesTheSameCornerGeometryAsXllcorner() throws IOException {
        Dem corner = DemReader.read(Path.of("testdata", "dem", "luxembourg_srtm30s_wgs84.flt"));
        LoadedDem center = DemReader.load(VARIANTS.resolve("luxembourg_g02_gridfloat_xllcenter.flt"),
                ReadRequest.FULL);
        assertSameGeotransform(corner.geometry(), center.dem().geometry(), 1e-12, "xllcenter vs xllcorner");
        assertEquals(PixelAnchor.CENTER, center.info().geometry().declaredAnchor());
        assertEquals(PixelAnchor.CORNER, corner.geometry().declaredAnchor());
    }

    @Test
    void msbFirstGridFloatEqualsLsbFirst() throws IOException {
        Dem lsb = DemReader.read(Path.of("testdata", "dem", "luxembourg_srtm30s_wgs84.flt"));
        Dem msb = DemReader.read(VARIANTS.resolve("luxembourg_g01_gridfloat_msbfirst.flt"));
        assertSameValues(lsb, msb, "MSBFIRST");
    }
}
