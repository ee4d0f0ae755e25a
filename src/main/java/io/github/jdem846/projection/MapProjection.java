package io.github.jdem846.projection;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.CrsResolver;
import io.github.jdem846.internal.SisLoggers;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import org.apache.sis.measure.Units;
import org.apache.sis.parameter.ParameterBuilder;
import org.apache.sis.referencing.CRS;
import org.apache.sis.referencing.CommonCRS;
import org.apache.sis.referencing.crs.DefaultProjectedCRS;
import org.apache.sis.referencing.operation.DefaultConversion;
import org.apache.sis.referencing.operation.DefaultOperationMethod;
import org.opengis.parameter.GeneralParameterValue;
import org.opengis.parameter.ParameterDescriptor;
import org.opengis.parameter.ParameterDescriptorGroup;
import org.opengis.parameter.ParameterValue;
import org.opengis.parameter.ParameterValueGroup;
import org.opengis.referencing.crs.CoordinateReferenceSystem;
import org.opengis.referencing.crs.ProjectedCRS;
import org.opengis.referencing.operation.MathTransform;
import org.opengis.util.FactoryException;

/**
 * The projection of a projected picture: an Apache SIS {@link ProjectedCRS} (for georeferencing and for the
 * transforms between it and the DEM's CRS), the latitude band it can show and its central meridian.
 *
 * <p>Made from a {@linkplain #named name} ({@link ProjectionName}), an {@linkplain #fromEpsg EPSG code} Apache SIS
 * knows offline (e.g. 3395, 3857, the UTM zones 326xx/327xx; without the EPSG database SIS does not know 3035 or
 * 2154: give their WKT instead), or {@linkplain #fromWkt WKT} (a {@code .prj}). Immutable.
 */
public final class MapProjection {

    static {
        SisLoggers.quiet(); // SIS's routine warnings off stderr, unless the application configured them
    }

    /** The sphere radius of the sphere-only projections: the WGS 84 semi-major axis, as PROJ and ESRI use it. */
    public static final double SPHERE_RADIUS = 6_378_137.0;

    /** The latitude at which a square Mercator world ends, ±85.0511°. */
    public static final double MERCATOR_LATITUDE_LIMIT = Math.toDegrees(Math.atan(Math.sinh(Math.PI)));

    private static final String WGS84_GEOGCS = "GEOGCS[\"WGS 84\",DATUM[\"WGS_1984\",SPHEROID[\"WGS 84\",6378137,"
            + "298.257223563]],PRIMEM[\"Greenwich\",0],UNIT[\"degree\",0.0174532925199433]]";
    private static final String SPHERE_GEOGCS = "GEOGCS[\"Sphere\",DATUM[\"Sphere\",SPHEROID[\"Sphere\",6378137,"
            + "0]],PRIMEM[\"Greenwich\",0],UNIT[\"degree\",0.0174532925199433]]";

    private final String label;
    private final ProjectedCRS crs;
    private final Integer epsg;
    private final double centralMeridian;
    private final double latitudeLimit;

    private MapProjection(String label, ProjectedCRS crs, Integer epsg, double centralMeridian) {
        this.label = label;
        this.crs = crs;
        this.epsg = epsg;
        this.centralMeridian = centralMeridian;
        String method = crs.getConversionFromBase().getMethod().getName().getCode().toLowerCase(Locale.ROOT);
        this.latitudeLimit = method.contains("mercator") && !method.contains("transverse")
                && !method.contains("oblique") ? MERCATOR_LATITUDE_LIMIT : 90;
    }

    /**
     * A projection by name about a central meridian.
     *
     * @param name            the projection
     * @param centralMeridian λ₀ in degrees, in [−180, 180]
     * @return the projection on WGS 84 (sphere-only projections on a sphere of radius {@link #SPHERE_RADIUS})
     */
    public static MapProjection named(ProjectionName name, double centralMeridian) {
        Objects.requireNonNull(name, "name");
        if (!(centralMeridian >= -180 && centralMeridian <= 180)) {
            throw new IllegalArgumentException("a central meridian must be in [-180, 180] degrees, got "
                    + centralMeridian);
        }
        double cm = centralMeridian;
        String label = name.cliName() + (cm != 0 ? String.format(Locale.ROOT, " (central meridian %s°)", cm) : "");
        ProjectedCRS crs = switch (name) {
            case MERCATOR -> parse(String.format(Locale.ROOT, "PROJCS[\"WGS 84 / Mercator\",%s,"
                    + "PROJECTION[\"Mercator_1SP\"],PARAMETER[\"central_meridian\",%s],PARAMETER[\"scale_factor\",1],"
                    + "PARAMETER[\"false_easting\",0],PARAMETER[\"false_northing\",0],UNIT[\"metre\",1]]",
                    WGS84_GEOGCS, cm));
            case TRANSVERSE_MERCATOR -> parse(String.format(Locale.ROOT, "PROJCS[\"WGS 84 / Transverse Mercator\","
                    + "%s,PROJECTION[\"Transverse_Mercator\"],PARAMETER[\"latitude_of_origin\",0],"
                    + "PARAMETER[\"central_meridian\",%s],PARAMETER[\"scale_factor\",1],"
                    + "PARAMETER[\"false_easting\",0],PARAMETER[\"false_northing\",0],UNIT[\"metre\",1]]",
                    WGS84_GEOGCS, cm));
            case EQUIRECTANGULAR -> onSphere("World_Equirectangular", "Equirectangular", cm, true);
            case ROBINSON -> onSphere("World_Robinson", "Robinson", cm, false);
            case MOLLWEIDE -> onSphere("World_Mollweide", "Mollweide", cm, false);
            case WINKEL_TRIPEL -> formula("World_Winkel_Tripel", new WinkelTripel(), cm);
            case HAMMER -> formula("World_Hammer_Aitoff", new Hammer(), cm);
            case AITOFF -> formula("World_Aitoff", new Aitoff(), cm);
            case WAGNER_VI -> formula("World_Wagner_VI", new WagnerVI(), cm);
        };
        return new MapProjection(label, crs, null, cm);
    }

    /**
     * A projected CRS by EPSG code, when Apache SIS can build it offline.
     *
     * @param code the EPSG code
     * @return the projection
     * @throws IllegalArgumentException when SIS does not know the code offline or the CRS is not projected
     */
    public static MapProjection fromEpsg(int code) {
        CoordinateReferenceSystem crs = CrsResolver.fromEpsg(code).flatMap(CrsInfo::sis).orElseThrow(
                () -> new IllegalArgumentException("EPSG:" + code + " is not a CRS Apache SIS knows without the EPSG "
                        + "database; give its WKT (a .prj file) instead"));
        if (!(crs instanceof ProjectedCRS p)) {
            throw new IllegalArgumentException("EPSG:" + code + " is not a projected CRS (" + crs.getName().getCode()
                    + ")");
        }
        return new MapProjection("EPSG:" + code + " (" + p.getName().getCode() + ")", p, code, centralMeridianOf(p));
    }

    /**
     * A projected CRS from WKT 1 or 2 (e.g. the content of a {@code .prj}).
     *
     * @param wkt the text
     * @return the projection
     * @throws IllegalArgumentException when SIS cannot parse it or it is not a projected CRS
     */
    public static MapProjection fromWkt(String wkt) {
        CrsInfo info = CrsResolver.complete(CrsResolver.fromWkt(wkt));
        if (!(info.sisCrs() instanceof ProjectedCRS p)) {
            throw new IllegalArgumentException("the WKT is not a projected CRS"
                    + (info.name() != null ? " ('" + info.name() + "')" : ""));
        }
        return new MapProjection(p.getName().getCode(), p, info.epsg(), centralMeridianOf(p));
    }

    /** {@return a short description, e.g. "robinson" or "EPSG:3395 (WGS 84 / World Mercator)"} */
    public String label() {
        return label;
    }

    /** {@return the projected CRS, east–north axes in metres (or the CRS's unit)} */
    public ProjectedCRS crs() {
        return crs;
    }

    /** {@return the CRS as the writers take it: EPSG code when known, else WKT from the SIS object} */
    public CrsInfo crsInfo() {
        return CrsResolver.fromSis(crs, epsg);
    }

    /** {@return the central meridian in degrees (0 when the CRS names none)} */
    public double centralMeridian() {
        return centralMeridian;
    }

    /** {@return the largest |latitude| the picture shows: 90°, or {@link #MERCATOR_LATITUDE_LIMIT} for Mercator} */
    public double latitudeLimit() {
        return latitudeLimit;
    }

    @Override
    public String toString() {
        return label;
    }

    private static ProjectedCRS parse(String wkt) {
        try {
            return (ProjectedCRS) CRS.fromWKT(wkt);
        } catch (FactoryException e) {
            throw new IllegalStateException("a built-in projection's WKT does not parse: " + e.getMessage(), e);
        }
    }

    /**
     * A projection Apache SIS implements, computed by SIS on a sphere of radius a (SIS would use the authalic
     * sphere of an ellipsoid, 0.11 % smaller than PROJ's and ESRI's), declared on WGS 84 as PROJ and ESRI do.
     */
    private static ProjectedCRS onSphere(String name, String method, double cm, boolean standardParallel) {
        String parallel = standardParallel ? ",PARAMETER[\"standard_parallel_1\",0]" : "";
        ProjectedCRS sphere = parse(String.format(Locale.ROOT, "PROJCS[\"%s\",%s,PROJECTION[\"%s\"],"
                + "PARAMETER[\"central_meridian\",%s]%s,PARAMETER[\"false_easting\",0],"
                + "PARAMETER[\"false_northing\",0],UNIT[\"metre\",1]]", name, SPHERE_GEOGCS, method, cm, parallel));
        return declare(name, method, sphere.getConversionFromBase().getMathTransform(), cm,
                standardParallel ? 0.0 : null);
    }

    /** A projection of {@link SphericalFormula}, on a sphere of radius a, declared on WGS 84. */
    private static ProjectedCRS formula(String name, SphericalFormula formula, double cm) {
        Double parallel = formula instanceof WinkelTripel w ? w.standardParallel() : null;
        return declare(name, formula.wktName(), new FormulaTransform(formula, SPHERE_RADIUS, cm), cm, parallel);
    }

    /**
     * A projected CRS on WGS 84 (longitude, latitude in degrees) with the given transform and a method of the
     * given name and parameters (ESRI's names, which GDAL and PROJ read).
     */
    private static ProjectedCRS declare(String name, String method, MathTransform transform, double cm,
                                        Double standardParallel) {
        ParameterBuilder b = new ParameterBuilder();
        ParameterDescriptor<Double> falseEasting = b.addName("False_Easting").create(0.0, Units.METRE);
        ParameterDescriptor<Double> falseNorthing = b.addName("False_Northing").create(0.0, Units.METRE);
        ParameterDescriptor<Double> centralMeridian = b.addName("Central_Meridian").create(0.0, Units.DEGREE);
        ParameterDescriptor<Double> parallel = b.addName("Standard_Parallel_1").create(0.0, Units.DEGREE);
        ParameterDescriptorGroup group = standardParallel == null
                ? b.addName(method).createGroup(falseEasting, falseNorthing, centralMeridian)
                : b.addName(method).createGroup(falseEasting, falseNorthing, centralMeridian, parallel);
        ParameterValueGroup values = group.createValue();
        values.parameter("Central_Meridian").setValue(cm);
        if (standardParallel != null) {
            values.parameter("Standard_Parallel_1").setValue(standardParallel.doubleValue());
        }
        DefaultOperationMethod operation = new DefaultOperationMethod(Map.of("name", method), group);
        DefaultConversion conversion = new DefaultConversion(Map.of("name", name), operation, transform, values);
        return new DefaultProjectedCRS(Map.of("name", name), CommonCRS.WGS84.normalizedGeographic(), conversion,
                CommonCRS.WGS84.universal(0, 0).getCoordinateSystem());
    }

    /** The value of the CRS's central meridian parameter (by its EPSG or OGC name), or 0. */
    private static double centralMeridianOf(ProjectedCRS crs) {
        ParameterValueGroup values = crs.getConversionFromBase().getParameterValues();
        for (GeneralParameterValue v : values.values()) {
            String n = v.getDescriptor().getName().getCode().toLowerCase(Locale.ROOT);
            if (v instanceof ParameterValue<?> p && (n.contains("central") && n.contains("meridian")
                    || n.contains("longitude of natural origin") || n.contains("longitude of origin")
                    || n.contains("longitude of false origin") || n.contains("longitude of projection centre"))) {
                try {
                    return p.doubleValue(Units.DEGREE);
                } catch (RuntimeException e) {
                    return 0;
                }
            }
        }
        return 0;
    }
}
