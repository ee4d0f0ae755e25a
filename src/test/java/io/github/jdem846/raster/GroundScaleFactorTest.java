package io.github.jdem846.raster;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

class GroundScaleFactorTest {

    @Test
    void webMercatorScaleIsTheSecantOfTheLatitude() throws IOException {
        GridGeometry g = DemReader.inspect(Path.of("testdata/dem/vancouver-island_topobathy_2min_mercator.tif"))
                .geometry();
        double lat = g.cellCenterLatLon(g.width() / 2, g.height() / 2).orElseThrow().latitude();
        // Spherical Mercator of WGS 84 lat/lon measured on the WGS 84 ellipsoid: k = cos⁻¹φ · √(1 − e² sin²φ)
        double e2 = 0.00669437999014;
        double s = Math.sin(Math.toRadians(lat));
        double expected = Math.sqrt(1 - e2 * s * s) / Math.cos(Math.toRadians(lat));
        assertEquals(expected, g.groundScaleFactor().orElseThrow(), 2e-3 * expected);
    }

    @Test
    void utmScaleIsNearOne() throws IOException {
        GridGeometry g = DemReader.inspect(Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif")).geometry();
        double k = g.groundScaleFactor().orElseThrow();
        assertTrue(k > 0.9996 - 1e-4 && k < 1.0010, "UTM scale factor " + k);
    }

    @Test
    void geographicAndUnknownGridsHaveNone() throws IOException {
        assertTrue(DemReader.inspect(Path.of("testdata/dem/luxembourg_srtm30s_wgs84.tif")).geometry()
                .groundScaleFactor().isEmpty());
        assertTrue(GridGeometry.metric(3, 3, 1).groundScaleFactor().isEmpty());
    }
}
