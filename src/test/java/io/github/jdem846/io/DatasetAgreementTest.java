package io.github.jdem846.io;

import static io.github.jdem846.io.DemAssertions.assertSameGeotransform;
import static io.github.jdem846.io.DemAssertions.assertSameValues;
import static org.junit.jupiter.api.Assertions.assertEquals;

import io.github.jdem846.raster.Dem;
import io.github.jdem846.testing.TestDems;
import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The GeoTIFF and the GridFloat of each dataset of testdata/dem agree bit for bit and in georeferencing, and both
 * agree with the independent loader of {@link TestDems} and with the summary table of testdata/PROVENANCE.md.
 */
class DatasetAgreementTest {

    @ParameterizedTest
    @ValueSource(strings = {TestDems.BIG_TUJUNGA, TestDems.JACKSBORO, TestDems.LUXEMBOURG, TestDems.VANCOUVER,
        TestDems.VOLCANO})
    void geoTiffAndGridFloatAgree(String name) throws IOException {
        Dem tif = DemReader.read(TestDems.DEM_DIR.resolve(name + ".tif"));
        Dem flt = DemReader.read(TestDems.DEM_DIR.resolve(name + ".flt"));
        Dem reference = TestDems.load(name);
        assertSameValues(flt, tif, name + " GeoTIFF vs GridFloat");
        assertSameValues(reference, flt, name + " GridFloat vs the independent loader");
        assertSameGeotransform(flt.geometry(), tif.geometry(), 1e-9, name);
        assertSameGeotransform(reference.geometry(), flt.geometry(), 1e-15, name + " vs the independent loader");
        assertEquals(reference.geometry().crs().kind(), tif.geometry().crs().kind(), name + " CRS kind (GeoTIFF)");
        assertEquals(reference.geometry().crs().kind(), flt.geometry().crs().kind(), name + " CRS kind (.prj)");
        if (!tif.geometry().crs().isGeographic()) {
            assertEquals(1.0, tif.geometry().crs().linearUnitMeters(), name + " unit (GeoTIFF)");
            assertEquals(1.0, flt.geometry().crs().linearUnitMeters(), name + " unit (.prj)");
        }
        assertEquals(reference.geometry().crs().epsg(), tif.geometry().crs().epsg(), name + " EPSG (GeoTIFF)");
    }

    @ParameterizedTest
    @ValueSource(strings = {
        "bigtujunga_srtm30m_utm11n,1197,643,315,2295,0",
        "luxembourg_srtm30s_wgs84,95,90,141,547,3942",
        "jacksboro_srtm3s_wgs84,403,344,236,1076,0",
        "vancouver-island_topobathy_2min_mercator,120,91,-1437,2205,0",
        "maungawhau-volcano_10m_nztm-approx,61,87,94,195,0"})
    void summaryTableOfProvenanceHolds(String row) throws IOException {
        String[] f = row.split(",");
        for (String ext : new String[] {".tif", ".flt"}) {
            Path file = TestDems.DEM_DIR.resolve(f[0] + ext);
            Dem dem = DemReader.read(file);
            assertEquals(Integer.parseInt(f[1]), dem.width(), file + " columns");
            assertEquals(Integer.parseInt(f[2]), dem.height(), file + " rows");
            assertEquals(Double.parseDouble(f[3]), dem.statistics().min(), file + " min");
            assertEquals(Double.parseDouble(f[4]), dem.statistics().max(), file + " max");
            assertEquals(Long.parseLong(f[5]), dem.statistics().noDataCount(), file + " no-data cells");
            assertEquals(dem.statistics(), DemReader.statistics(file), file + " streamed statistics");
        }
    }
}
