package io.github.jdem846.geo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.testing.TestDems;
import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * Latitude/longitude of grid positions, against PROJ (Debian gdal-bin 3.6.2 {@code gdaltransform}; commands in
 * each test) and against facts in testdata/PROVENANCE.md.
 */
class GeoLocatorTest {

    @Test
    void utmCornersMatchGdaltransform() throws IOException {
        // printf "388913.655454 3804317.827628\n406913.655454 3792317.827628\n" |
        //   gdaltransform -s_srs EPSG:32611 -t_srs EPSG:4326 -output_xy
        GridGeometry g = DemReader.read(Path.of(
                "testdata/variants/bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif")).geometry();
        GeoLocator l = g.geoLocator().orElseThrow();
        LatLon nw = l.toLatLon(g.originX(), g.originY());
        LatLon se = l.toLatLon(g.eastX(), g.southY());
        assertEquals(-118.20820449866, nw.longitude(), 1e-9);
        assertEquals(34.3742783631901, nw.latitude(), 1e-9);
        assertEquals(-118.011162552414, se.longitude(), 1e-9);
        assertEquals(34.2678499723531, se.latitude(), 1e-9);
    }

    @Test
    void lonLatGoBackToTheGdaltransformUtmPositions() throws IOException {
        // the same two points as utmCornersMatchGdaltransform, the other way, in one batch
        GridGeometry g = DemReader.read(Path.of(
                "testdata/variants/bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif")).geometry();
        double[] p = {-118.20820449866, 34.3742783631901, -118.011162552414, 34.2678499723531};
        g.geoLocator().orElseThrow().fromLonLat(p, 2);
        assertEquals(388913.655454, p[0], 1e-3);
        assertEquals(3804317.827628, p[1], 1e-3);
        assertEquals(406913.655454, p[2], 1e-3);
        assertEquals(3792317.827628, p[3], 1e-3);
        double[] geographic = {7.5, 46.25};
        GeoLocator.forCrs(CrsInfo.WGS84).orElseThrow().fromLonLat(geographic, 1);
        assertEquals(7.5, geographic[0], 0);
        assertEquals(46.25, geographic[1], 0);
    }

    @Test
    void utmExtentMatchesGdalinfoWgs84Extent() throws IOException {
        // gdalinfo -json testdata/dem/bigtujunga_srtm30m_utm11n.tif → wgs84Extent corners:
        // (-118.3457332, 34.405306) (-118.3429599, 34.2313881) (-117.953114, 34.2350384) (-117.9550826, 34.4089801)
        GridGeometry g = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.BIG_TUJUNGA + ".tif")).geometry();
        LatLonBox box = g.latLonExtent().orElseThrow();
        assertEquals(-118.3457332, box.west(), 1e-7);
        assertEquals(-117.953114, box.east(), 1e-7);
        assertEquals(34.2313881, box.south(), 1e-7);
        assertEquals(34.4089801, box.north(), 1e-7);
    }

    @Test
    void nztmPrjGivesTheSummitRegion() throws IOException {
        // printf "1756944 5917994\n" | gdaltransform -s_srs "$(cat testdata/dem/maungawhau-...prj)" -t_srs EPSG:4326
        GridGeometry g = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.VOLCANO + ".flt")).geometry();
        LatLon nw = g.geoLocator().orElseThrow().toLatLon(g.originX(), g.originY());
        assertEquals(174.760840686223, nw.longitude(), 1e-9);
        assertEquals(-36.8709691909241, nw.latitude(), 1e-9);
        // PROVENANCE: the highest cell (row 67, col 30) sits on the summit, 174.7644°E 36.8770°S, ±100 m.
        LatLon summit = g.cellCenterLatLon(30, 67).orElseThrow();
        assertEquals(174.7644, summit.longitude(), 0.0012);
        assertEquals(-36.8770, summit.latitude(), 0.0009);
    }

    @Test
    void mercatorGridEdgesAreWholeDegreesOfLongitude() throws IOException {
        // PROVENANCE: the west edge is exactly 126°W and the east edge 122°W.
        for (String ext : new String[] {".tif", ".flt"}) {
            GridGeometry g = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.VANCOUVER + ext)).geometry();
            LatLonBox box = g.latLonExtent().orElseThrow();
            assertEquals(-126.0, box.west(), 1e-9, ext);
            assertEquals(-122.0, box.east(), 1e-9, ext);
            // gdaltransform -s_srs EPSG:3857 -t_srs EPSG:4326: north edge 49.9948990093294
            assertEquals(49.9948990093294, box.north(), 1e-9, ext);
        }
    }

    @Test
    void geographicIsTheIdentity() throws IOException {
        GridGeometry g = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.JACKSBORO + ".tif")).geometry();
        LatLon p = g.cellCenterLatLon(0, 0).orElseThrow();
        assertEquals(g.centerY(0), p.latitude(), 0);
        assertEquals(g.centerX(0), p.longitude(), 0);
        assertEquals(new LatLonBox(g.southY(), g.originY(), g.originX(), g.eastX()), g.latLonExtent().orElseThrow());
    }

    @Test
    void unknownOrUnresolvedCrsHasNoLocator() throws IOException {
        assertTrue(GeoLocator.forCrs(CrsInfo.UNKNOWN).isEmpty());
        GridGeometry nztmFromGeoKeys = DemReader.inspect(TestDems.DEM_DIR.resolve(TestDems.VOLCANO + ".tif"))
                .geometry();
        assertTrue(nztmFromGeoKeys.latLonExtent().isEmpty(), "EPSG:2193 is not in SIS's offline subset");
    }
}
