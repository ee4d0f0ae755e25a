package io.github.jdem846.geo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.apache.sis.referencing.CRS;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The WKT recognised without Apache SIS describes the same CRS as SIS's parse of the same text: kind, unit,
 * ellipsoid, EPSG code, and the latitude/longitude of points (through {@link CrsResolver#complete}). GDAL-written
 * ESRI and OGC WKT (testdata/crs/README.md) and the testdata DEMs' own {@code .prj}; near misses go to SIS.
 */
class CommonCrsWktTest {

    private static final Path CRS_DIR = Path.of("testdata", "crs");

    private static String read(String name) throws IOException {
        return Files.readString(CRS_DIR.resolve(name));
    }

    /** SIS's parse, bypassing the shortcut. */
    private static CrsInfo bySis(String wkt) throws Exception {
        return CrsResolver.fromSis(CRS.fromWKT(wkt), null);
    }

    @ParameterizedTest
    @ValueSource(strings = {"epsg4326_esri.prj", "epsg4326_ogc.prj", "epsg4269_esri.prj", "epsg4269_ogc.prj",
        "epsg32611_esri.prj", "epsg32611_ogc.prj", "epsg32733_esri.prj", "epsg32733_ogc.prj",
        "epsg26913_esri.prj", "epsg26913_ogc.prj", "epsg25832_esri.prj", "epsg25832_ogc.prj",
        "epsg4258_esri.prj", "epsg4258_ogc.prj", "../dem/bigtujunga_srtm30m_utm11n.prj",
        "../dem/luxembourg_srtm30s_wgs84.prj", "../dem/jacksboro_srtm3s_wgs84.prj"})
    void recognisedWktIsTheCrsSisReads(String name) throws Exception {
        String wkt = read(name);
        Optional<CrsInfo> quick = CommonCrsWkt.recognize(wkt);
        assertTrue(quick.isPresent(), name + " should be recognised");
        CrsInfo q = quick.get();
        CrsInfo sis = bySis(wkt);
        assertEquals(sis.kind(), q.kind(), name);
        assertEquals(sis.isGeographic() ? Double.NaN : sis.linearUnitMeters(), q.linearUnitMeters(), name);
        assertEquals(sis.ellipsoid().semiMajorAxis(), q.ellipsoid().semiMajorAxis(), name);
        assertEquals(sis.ellipsoid().inverseFlattening(), q.ellipsoid().inverseFlattening(), 1e-9, name);
        if (name.startsWith("epsg")) {
            assertEquals(Integer.valueOf(name.substring(4, name.indexOf('_'))), q.epsg(), name);
        }
        if (!q.isGeographic()) {
            GeoLocator mine = GeoLocator.forCrs(CrsResolver.complete(q)).orElseThrow();
            GeoLocator theirs = GeoLocator.forCrs(sis).orElseThrow();
            boolean south = q.epsg() / 100 == 327;
            for (double[] xy : new double[][] {{500_000, south ? 6_000_000 : 3_800_000}, {380_000,
                south ? 7_500_000 : 4_100_000}, {710_000, south ? 9_000_000 : 1_000_000}}) {
                LatLon a = mine.toLatLon(xy[0], xy[1]);
                LatLon b = theirs.toLatLon(xy[0], xy[1]);
                assertEquals(b.latitude(), a.latitude(), 1e-9, name);
                assertEquals(b.longitude(), a.longitude(), 1e-9, name);
            }
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"epsg4267_esri.prj", "epsg4267_ogc.prj", "epsg2193_esri.prj",
        "epsg2193_ogc.prj", "epsg3857_esri.prj", "epsg3857_ogc.prj", "epsg26711_esri.prj", "epsg26711_ogc.prj",
        "../dem/maungawhau-volcano_10m_nztm-approx.prj", "../dem/vancouver-island_topobathy_2min_mercator.prj"})
    void otherCrsAreLeftToSis(String name) throws Exception {
        assertTrue(CommonCrsWkt.recognize(read(name)).isEmpty(), name);
        assertTrue(CrsResolver.fromWkt(read(name)).sisCrs() != null, name + " parsed by SIS");
    }

    @Test
    void nearMissesAreLeftToSis() throws IOException {
        String utm = read("epsg32611_esri.prj");
        String geographic = read("epsg4326_esri.prj");
        List<String> nearMisses = List.of(
                utm.replace("0.9996", "0.9995"),
                utm.replace("-117.0", "-116.5"),
                utm.replace("PARAMETER[\"False_Northing\",0.0]", "PARAMETER[\"False_Northing\",5000000.0]"),
                utm.replace("UNIT[\"Meter\",1.0]", "UNIT[\"Foot_US\",0.3048006096012192]"),
                utm.replace("PARAMETER[\"Latitude_Of_Origin\",0.0]", "PARAMETER[\"Latitude_Of_Origin\",0.0],"
                        + "PARAMETER[\"Scale_Factor\",0.9996]"),
                utm.replace("Transverse_Mercator", "Mercator"),
                read("epsg26913_esri.prj").replace("False_Northing\",0.0", "False_Northing\",10000000.0"),
                read("epsg25832_esri.prj").replace("Central_Meridian\",9.0", "Central_Meridian\",45.0"),
                geographic.replace("PRIMEM[\"Greenwich\",0.0]", "PRIMEM[\"Paris\",2.33722917]"),
                geographic.replace("0.0174532925199433", "0.015707963267949"),
                geographic.replace("298.257223563", "298.3"),
                geographic.substring(0, geographic.length() - 1),
                geographic + "]",
                "GEOGCRS[\"WGS 84\",DATUM[\"World Geodetic System 1984\",ELLIPSOID[\"WGS 84\",6378137,298.257223563]],"
                        + "CS[ellipsoidal,2],AXIS[\"lat\",north],AXIS[\"lon\",east],ANGLEUNIT[\"degree\","
                        + "0.0174532925199433]]");
        for (String wkt : nearMisses) {
            assertTrue(CommonCrsWkt.recognize(wkt).isEmpty(), wkt);
        }
    }
}
