package io.github.jdem846.geo;

import io.github.jdem846.internal.SisLoggers;
import java.util.Optional;
import javax.measure.Unit;
import javax.measure.UnitConverter;
import javax.measure.IncommensurableException;
import org.apache.sis.measure.Units;
import org.apache.sis.metadata.iso.citation.Citations;
import org.apache.sis.referencing.CRS;
import org.apache.sis.referencing.CommonCRS;
import org.apache.sis.referencing.IdentifiedObjects;
import org.apache.sis.referencing.crs.AbstractCRS;
import org.apache.sis.referencing.cs.AxesConvention;
import org.opengis.metadata.Identifier;
import org.opengis.referencing.IdentifiedObject;
import org.opengis.referencing.crs.CoordinateReferenceSystem;
import org.opengis.referencing.crs.GeodeticCRS;
import org.opengis.referencing.crs.SingleCRS;
import org.opengis.referencing.cs.CartesianCS;
import org.opengis.referencing.cs.CoordinateSystem;
import org.opengis.referencing.cs.EllipsoidalCS;
import org.opengis.referencing.datum.Datum;
import org.opengis.referencing.datum.GeodeticDatum;
import org.opengis.util.FactoryException;

/**
 * Turns what a file says about its coordinate reference system (an EPSG code, an ESRI/OGC WKT string, or an Apache
 * SIS object) into a {@link CrsInfo}, offline.
 *
 * <p>Apache SIS 1.6 without the EPSG database knows only a subset of EPSG (e.g. 4326, 4269, 4267, 3857 and the UTM
 * zones 326xx/327xx, but not 2193 or 2227); codes outside it yield {@link Optional#empty()} so that callers can fall
 * back on what else the file says (GeoTIFF GeoKeys). Nothing here throws for an unknown CRS.
 *
 * <p>The SIS CRS kept in {@link CrsInfo#sisCrs()} is normalised to east–north axis order ("right-handed"), which
 * is the order of grid x and y, whatever order the EPSG definition uses.
 */
public final class CrsResolver {

    private CrsResolver() {
    }

    /**
     * Quiets SIS's routine warnings (unless the application configured them) before a use of SIS; not in a static
     * initialiser, since a common {@code .prj} is read without SIS and java.util.logging takes tens of
     * milliseconds to start on a cold JVM.
     */
    private static void beforeSis() {
        SisLoggers.quiet();
    }

    /**
     * The CRS of an EPSG code, when Apache SIS can build it offline.
     *
     * @param code the EPSG code, e.g. 4326 or 32632
     * @return the CRS, or empty when SIS cannot build the code offline
     */
    public static Optional<CrsInfo> fromEpsg(int code) {
        if (code <= 0 || code >= 32767) {
            return Optional.empty();
        }
        beforeSis();
        try {
            return Optional.of(fromSis(CRS.forCode("EPSG:" + code), code));
        } catch (FactoryException | RuntimeException e) {
            return Optional.empty();
        }
    }

    /**
     * The same CRS with Apache SIS's definition (name, ellipsoid, SIS object) when a reader kept only its EPSG code
     * (a GeoTIFF's geographic CRS is read from its GeoKeys without starting SIS); {@code crs} itself when SIS
     * already resolved it, when it has no code, or when SIS does not know the code offline or gives another kind.
     * The "assumed" flag is kept.
     *
     * @param crs the CRS as a reader described it
     * @return the completed CRS, or {@code crs} itself
     */
    public static CrsInfo complete(CrsInfo crs) {
        if (crs.sisCrs() != null || crs.epsg() == null) {
            return crs;
        }
        return fromEpsg(crs.epsg()).filter(c -> c.kind() == crs.kind())
                .map(c -> crs.assumed() ? c.asAssumed() : c).orElse(crs);
    }

    /**
     * Parses an OGC or ESRI WKT 1/2 string (e.g. the content of an ESRI {@code .prj}). Geographic WGS 84, NAD83 and
     * ETRS89 and their UTM zones are recognised without Apache SIS and known by their EPSG code (SIS's definition
     * follows from {@link #complete} where needed); everything else is parsed by SIS.
     *
     * @param wkt the WKT text
     * @return the CRS it describes
     * @throws IllegalArgumentException when the text is not a CRS Apache SIS can parse; the message says why
     */
    public static CrsInfo fromWkt(String wkt) {
        if (wkt == null || wkt.isBlank()) {
            throw new IllegalArgumentException("the WKT text is empty");
        }
        Optional<CrsInfo> common = CommonCrsWkt.recognize(wkt.strip());
        if (common.isPresent()) {
            return common.get();
        }
        beforeSis();
        CoordinateReferenceSystem crs;
        try {
            crs = CRS.fromWKT(wkt.strip());
        } catch (FactoryException | RuntimeException e) {
            throw new IllegalArgumentException("not a CRS in WKT that Apache SIS can parse (" + e.getMessage() + ")",
                    e);
        }
        return fromSis(crs, null);
    }

    /**
     * Describes an Apache SIS CRS: kind from its coordinate system (ellipsoidal → geographic, Cartesian in a
     * length unit → projected), linear unit in metres, ellipsoid from its geodetic datum, EPSG code from the
     * argument or the CRS's own EPSG identifier. A compound CRS is described by its horizontal part.
     *
     * @param crs  the CRS
     * @param epsg the code it was created from, or {@code null} to take it from the CRS's identifiers
     * @return the description, with {@code crs} as its SIS object
     */
    public static CrsInfo fromSis(CoordinateReferenceSystem crs, Integer epsg) {
        beforeSis();
        SingleCRS horizontal = CRS.getHorizontalComponent(crs);
        CoordinateReferenceSystem base = horizontal != null ? horizontal : crs;
        CoordinateReferenceSystem oriented = AbstractCRS.castOrCopy(base).forConvention(AxesConvention.RIGHT_HANDED);
        String name = oriented.getName() != null ? oriented.getName().getCode() : null;
        Integer code = epsg != null ? epsg : epsgIdentifier(crs);
        Ellipsoid ellipsoid = oriented instanceof SingleCRS s ? ellipsoidOf(s.getDatum()) : null;
        CoordinateSystem cs = oriented.getCoordinateSystem();
        if (cs instanceof EllipsoidalCS && cs.getDimension() >= 2 && isDegrees(cs.getAxis(0).getUnit())) {
            return new CrsInfo(name, code, CrsInfo.Kind.GEOGRAPHIC, Double.NaN, ellipsoid, oriented, false);
        }
        if (cs instanceof CartesianCS && cs.getDimension() >= 2 && !(oriented instanceof GeodeticCRS)) {
            double unit = metresPerUnit(cs.getAxis(0).getUnit());
            if (unit > 0) {
                return new CrsInfo(name, code, CrsInfo.Kind.PROJECTED, unit, ellipsoid, oriented, false);
            }
        }
        return new CrsInfo(name, code, CrsInfo.Kind.UNKNOWN, Double.NaN, ellipsoid, oriented, false);
    }

    /**
     * Metres per unit for an EPSG unit-of-measure code (9001 metre, 9002 foot, 9003 US survey foot, …), or NaN
     * when the code is unknown or not a length.
     *
     * @param epsgUnitCode the EPSG code of a unit of measure
     * @return metres per unit, or NaN
     */
    public static double linearUnitMetres(int epsgUnitCode) {
        beforeSis();
        Unit<?> unit = null;
        try {
            unit = Units.valueOfEPSG(epsgUnitCode);
        } catch (RuntimeException e) {
            // unknown code: fall through
        }
        return unit != null ? metresPerUnit(unit) : Double.NaN;
    }

    /**
     * The name of an EPSG unit-of-measure code ("metre", "US survey foot"), or "EPSG unit {@literal <code>}".
     *
     * @param epsgUnitCode the EPSG code of a unit of measure
     * @return the unit's name
     */
    public static String linearUnitName(int epsgUnitCode) {
        return switch (epsgUnitCode) {
            case 9001 -> "metre";
            case 9002 -> "foot";
            case 9003 -> "US survey foot";
            case 9036 -> "kilometre";
            default -> "EPSG unit " + epsgUnitCode;
        };
    }

    /**
     * The ellipsoid of an EPSG ellipsoid code (7030 WGS 84, 7019 GRS 1980, 7008 Clarke 1866, …) among those
     * Apache SIS knows offline.
     *
     * @param code the EPSG code of an ellipsoid
     * @return the ellipsoid, or empty when the code is unknown offline or not an ellipsoid
     */
    public static Optional<Ellipsoid> ellipsoidFromEpsg(int code) {
        beforeSis();
        for (CommonCRS c : CommonCRS.values()) {
            org.opengis.referencing.datum.Ellipsoid e = c.ellipsoid();
            if (Integer.valueOf(code).equals(epsgIdentifier(e))) {
                return Optional.ofNullable(toEllipsoid(e));
            }
        }
        return Optional.empty();
    }

    /**
     * The ellipsoid of an EPSG geodetic datum code (6326 WGS 84, 6269 NAD83, 6267 NAD27, …) known offline.
     *
     * @param code the EPSG code of a geodetic datum
     * @return the datum's ellipsoid, or empty when the code is unknown offline or not a geodetic datum
     */
    public static Optional<Ellipsoid> ellipsoidOfDatumEpsg(int code) {
        beforeSis();
        for (CommonCRS c : CommonCRS.values()) {
            GeodeticDatum d = c.datum(false);
            if (d != null && Integer.valueOf(code).equals(epsgIdentifier(d))) {
                return Optional.ofNullable(toEllipsoid(d.getEllipsoid()));
            }
        }
        return Optional.empty();
    }

    private static Ellipsoid ellipsoidOf(Datum datum) {
        return datum instanceof GeodeticDatum g ? toEllipsoid(g.getEllipsoid()) : null;
    }

    private static Ellipsoid toEllipsoid(org.opengis.referencing.datum.Ellipsoid e) {
        if (e == null) {
            return null;
        }
        double toMetres = metresPerUnit(e.getAxisUnit());
        if (!(toMetres > 0)) {
            return null;
        }
        double a = e.getSemiMajorAxis() * toMetres;
        double invF = e.isSphere() ? Double.POSITIVE_INFINITY : e.getInverseFlattening();
        String name = e.getName() != null ? e.getName().getCode() : null;
        try {
            return new Ellipsoid(name, a, invF);
        } catch (IllegalArgumentException ex) {
            return null;
        }
    }

    private static Integer epsgIdentifier(IdentifiedObject object) {
        Identifier id = IdentifiedObjects.getIdentifier(object, Citations.EPSG);
        if (id == null) {
            return null;
        }
        try {
            return Integer.valueOf(id.getCode().trim());
        } catch (NumberFormatException e) {
            return null;
        }
    }

    private static boolean isDegrees(Unit<?> unit) {
        if (unit == null) {
            return false;
        }
        try {
            UnitConverter c = unit.getConverterToAny(Units.DEGREE);
            return Math.abs(c.convert(1.0) - 1.0) < 1e-9;
        } catch (IncommensurableException | RuntimeException e) {
            return false;
        }
    }

    private static double metresPerUnit(Unit<?> unit) {
        if (unit == null) {
            return Double.NaN;
        }
        try {
            return unit.getConverterToAny(Units.METRE).convert(1.0);
        } catch (IncommensurableException | RuntimeException e) {
            return Double.NaN;
        }
    }
}
