package io.github.jdem846.projection;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.LatLonBox;
import org.apache.sis.referencing.CRS;
import org.apache.sis.referencing.CommonCRS;
import org.junit.jupiter.api.Test;
import org.opengis.referencing.crs.CoordinateReferenceSystem;
import org.opengis.referencing.operation.MathTransform;

/**
 * Named projections as PROJ computes them (values from PROJ 9.1 via {@code gdaltransform -s_srs EPSG:4326 -t_srs
 * "+proj=… +datum=WGS84 +units=m" -output_xy}), Robinson against its published table, Mercator and transverse
 * Mercator against Apache SIS's EPSG definitions, and projections by EPSG code and WKT.
 */
class MapProjectionTest {

    private static double[] project(MapProjection p, double lon, double lat) throws Exception {
        return project(p.crs(), lon, lat);
    }

    private static double[] project(CoordinateReferenceSystem crs, double lon, double lat) throws Exception {
        MathTransform t = CRS.findOperation(CommonCRS.WGS84.normalizedGeographic(), crs, null).getMathTransform();
        double[] xy = {lon, lat};
        t.transform(xy, 0, xy, 0, 1);
        return xy;
    }

    private static void assertAt(MapProjection p, double lon, double lat, double x, double y, double tolerance)
            throws Exception {
        double[] xy = project(p, lon, lat);
        assertEquals(x, xy[0], tolerance, p + " x at " + lon + ", " + lat);
        assertEquals(y, xy[1], tolerance, p + " y at " + lon + ", " + lat);
    }

    @Test
    void sisProjectionsOnASphereOfRadiusAAsProjComputesThem() throws Exception {
        MapProjection moll = MapProjection.named(ProjectionName.MOLLWEIDE, 0);
        assertAt(moll, -84.2, 36.6, -7363541.75075492, 4405934.30249793, 1e-3);
        assertAt(moll, 120, -30, 11001704.4647197, -3643853.5640797, 1e-3);
        MapProjection eqc = MapProjection.named(ProjectionName.EQUIRECTANGULAR, 0);
        assertAt(eqc, -84.2, 36.6, -9373101.12479364, 4074293.36303381, 1e-3);
        assertAt(eqc, 180, 90, 20037508.3427892, 10018754.1713946, 1e-3);
        MapProjection wintri = MapProjection.named(ProjectionName.WINKEL_TRIPEL, 0);
        assertAt(wintri, -84.2, 36.6, -6969783.62329478, 4245022.76381855, 1e-3);
    }

    @Test
    void robinsonHitsItsTableAtTheNodesAndProjWithinAFewHundredMetres() throws Exception {
        MapProjection robin = MapProjection.named(ProjectionName.ROBINSON, 0);
        double r = MapProjection.SPHERE_RADIUS;
        // Snyder & Voxland's table: x = 0.8487 R X λ, y = 1.3523 R Y; X(35°) = 0.9427, Y(35°) = 0.4340,
        // X(50°) = 0.8679, Y(50°) = 0.6176, X(90°) = 0.5322, Y(90°) = 1
        assertAt(robin, 10, 35, 0.8487 * r * 0.9427 * Math.toRadians(10), 1.3523 * r * 0.4340, 1);
        assertAt(robin, -60, -50, 0.8487 * r * 0.8679 * Math.toRadians(-60), -1.3523 * r * 0.6176, 1);
        assertAt(robin, 180, 90, 0.8487 * r * 0.5322 * Math.PI, 1.3523 * r, 1);
        // between the nodes SIS and PROJ interpolate the table differently
        assertAt(robin, -84.2, 36.6, -7448995.17997225, 3914195.52342681, 300);
    }

    @Test
    void mercatorIsEpsg3395AndTransverseMercatorIsUtmUnscaled() throws Exception {
        CoordinateReferenceSystem worldMercator = CRS.forCode("EPSG:3395");
        double[] expected = project(worldMercator, -84.2, 36.6);
        assertAt(MapProjection.named(ProjectionName.MERCATOR, 0), -84.2, 36.6, expected[0], expected[1], 1e-6);
        assertEquals(MapProjection.MERCATOR_LATITUDE_LIMIT,
                MapProjection.named(ProjectionName.MERCATOR, 0).latitudeLimit(), 0);
        assertEquals(85.0511287798, MapProjection.MERCATOR_LATITUDE_LIMIT, 1e-9);
        // UTM zone 16N (central meridian −87°) = 500 km + 0.9996 × transverse Mercator about −87°
        double[] utm = project(CRS.forCode("EPSG:32616"), -84.2, 36.6);
        double[] tm = project(MapProjection.named(ProjectionName.TRANSVERSE_MERCATOR, -87), -84.2, 36.6);
        assertEquals(utm[0], 500000 + 0.9996 * tm[0], 1e-6);
        assertEquals(utm[1], 0.9996 * tm[1], 1e-6);
    }

    @Test
    void centralMeridianShiftsTheMap() throws Exception {
        MapProjection about100 = MapProjection.named(ProjectionName.WAGNER_VI, 100);
        double[] shifted = project(about100, 110, 20);
        double[] plain = project(MapProjection.named(ProjectionName.WAGNER_VI, 0), 10, 20);
        assertEquals(plain[0], shifted[0], 1e-6);
        assertEquals(plain[1], shifted[1], 1e-6);
        // −170° is 90° east of 100° across the antimeridian
        double[] across = project(about100, -170, 20);
        double[] ninety = project(MapProjection.named(ProjectionName.WAGNER_VI, 0), 90, 20);
        assertEquals(ninety[0], across[0], 1e-6);
    }

    @Test
    void byEpsgCodeAndByWkt() {
        MapProjection mercator = MapProjection.fromEpsg(3395);
        CrsInfo info = mercator.crsInfo();
        assertEquals(3395, info.epsg());
        assertEquals(CrsInfo.Kind.PROJECTED, info.kind());
        IllegalArgumentException unknown = assertThrows(IllegalArgumentException.class,
                () -> MapProjection.fromEpsg(3035));
        assertTrue(unknown.getMessage().contains("EPSG:3035") && unknown.getMessage().contains("WKT"),
                unknown.getMessage());
        IllegalArgumentException geographic = assertThrows(IllegalArgumentException.class,
                () -> MapProjection.fromEpsg(4326));
        assertTrue(geographic.getMessage().contains("not a projected CRS"), geographic.getMessage());
        String laea = "PROJCS[\"ETRS89-extended / LAEA Europe\",GEOGCS[\"ETRS89\",DATUM[\"European_Terrestrial_"
                + "Reference_System_1989\",SPHEROID[\"GRS 1980\",6378137,298.257222101]],PRIMEM[\"Greenwich\",0],"
                + "UNIT[\"degree\",0.0174532925199433]],PROJECTION[\"Lambert_Azimuthal_Equal_Area\"],"
                + "PARAMETER[\"latitude_of_center\",52],PARAMETER[\"longitude_of_center\",10],"
                + "PARAMETER[\"false_easting\",4321000],PARAMETER[\"false_northing\",3210000],UNIT[\"metre\",1]]";
        MapProjection europe = MapProjection.fromWkt(laea);
        assertEquals(10, europe.centralMeridian(), 0);
        assertNull(europe.crsInfo().epsg());
        assertEquals(90, europe.latitudeLimit(), 0);
    }

    @Test
    void namedProjectionsKeepTheirNameAndParametersForWriters() {
        MapProjection w = MapProjection.named(ProjectionName.WINKEL_TRIPEL, 12.5);
        CrsInfo info = w.crsInfo();
        assertEquals("World_Winkel_Tripel", info.name());
        assertEquals(CrsInfo.Kind.PROJECTED, info.kind());
        assertEquals(1.0, info.linearUnitMeters(), 0);
        String wkt = w.crs().toWKT();
        assertTrue(wkt.contains("Winkel_Tripel") && wkt.contains("12.5") && wkt.contains("50.4597"), wkt);
    }

    @Test
    void defaultCentralMeridian() {
        LatLonBox tennessee = new LatLonBox(36.4, 36.7, -84.4, -84.1);
        assertEquals(0, ProjectedRender.defaultCentralMeridian(ProjectionName.ROBINSON, tennessee), 0);
        assertEquals(-84.25, ProjectedRender.defaultCentralMeridian(ProjectionName.TRANSVERSE_MERCATOR, tennessee),
                1e-9);
        LatLonBox fiji = new LatLonBox(-20, -15, 175, 185);
        assertEquals(180, Math.abs(ProjectedRender.defaultCentralMeridian(ProjectionName.ROBINSON, fiji)), 0);
        LatLonBox world = new LatLonBox(-90, 90, 0, 360);
        assertEquals(0, ProjectedRender.defaultCentralMeridian(ProjectionName.MOLLWEIDE, world), 0);
    }

    @Test
    void namesAndAliases() {
        assertEquals(ProjectionName.WINKEL_TRIPEL, ProjectionName.of("Winkel Tripel").orElseThrow());
        assertEquals(ProjectionName.WAGNER_VI, ProjectionName.of("wag6").orElseThrow());
        assertEquals(ProjectionName.EQUIRECTANGULAR, ProjectionName.of("PLATE_CARREE").orElseThrow());
        assertTrue(ProjectionName.of("gnomonic").isEmpty());
    }
}
