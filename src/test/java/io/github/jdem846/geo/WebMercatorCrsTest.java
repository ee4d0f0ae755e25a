package io.github.jdem846.geo;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * {@link WebMercator#isWebMercator}: by EPSG code, and without one from Apache SIS's definition (the ESRI WKT GDAL
 * writes for EPSG:3857, as in the Vancouver Island GridFloat's {@code .prj}); near misses are other projections.
 */
class WebMercatorCrsTest {

    private static String read(String path) throws IOException {
        return Files.readString(Path.of(path));
    }

    @Test
    void byCodeOrByDefinition() throws IOException {
        assertTrue(WebMercator.isWebMercator(WebMercator.CRS));
        assertTrue(WebMercator.isWebMercator(CrsResolver.fromWkt(read("testdata/crs/epsg3857_ogc.prj"))));
        for (String esri : List.of("testdata/crs/epsg3857_esri.prj",
                "testdata/dem/vancouver-island_topobathy_2min_mercator.prj")) {
            CrsInfo crs = CrsResolver.fromWkt(read(esri));
            assertNull(crs.epsg(), esri + " names no code");
            assertTrue(WebMercator.isWebMercator(crs), esri);
        }
        String pseudo = read("testdata/crs/epsg3857_esri.prj").replace("Mercator_Auxiliary_Sphere\"]",
                "Popular_Visualisation_Pseudo_Mercator\"]").replace(",    PARAMETER[\"Standard_Parallel_1\",0.0],"
                + "    PARAMETER[\"Auxiliary_Sphere_Type\",0.0]", "");
        assertTrue(WebMercator.isWebMercator(CrsResolver.fromWkt(pseudo)), pseudo);
    }

    @Test
    void otherProjectionsAreNot() throws IOException {
        String esri = read("testdata/crs/epsg3857_esri.prj");
        List<String> others = List.of(
                esri.replace("\"Auxiliary_Sphere_Type\",0.0", "\"Auxiliary_Sphere_Type\",2.0"),
                esri.replace("\"Central_Meridian\",0.0", "\"Central_Meridian\",10.0"),
                esri.replace("\"False_Easting\",0.0", "\"False_Easting\",1000.0"),
                esri.replace("\"Standard_Parallel_1\",0.0", "\"Standard_Parallel_1\",30.0"),
                esri.replace("UNIT[\"Meter\",1.0]", "UNIT[\"Foot_US\",0.3048006096012192]"),
                esri.replace("6378137.0,298.257223563", "6378388.0,297.0"),
                read("testdata/crs/epsg2193_esri.prj"), read("testdata/crs/epsg26711_ogc.prj"));
        for (String wkt : others) {
            assertFalse(WebMercator.isWebMercator(CrsResolver.fromWkt(wkt)), wkt);
        }
        assertFalse(WebMercator.isWebMercator(UtmZone.ofEpsg(32611).orElseThrow().crsInfo()));
        assertFalse(WebMercator.isWebMercator(CrsInfo.WGS84));
    }
}
