package io.github.jdem846.render;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.shade.HillshadeMethod;
import io.github.jdem846.shade.HillshadeOptions;
import io.github.jdem846.shadow.ShadowAlgorithm;
import io.github.jdem846.shadow.ShadowOptions;
import io.github.jdem846.shadow.SkyView;
import io.github.jdem846.shadow.SkyViewOptions;
import io.github.jdem846.tint.ColorRamp;
import java.util.Objects;

/**
 * What to draw, independent of any particular DEM: the stages and their settings. Immutable; start from
 * {@link #defaults()} and change what you need with the {@code with…} methods. A stage set to {@code null} (or
 * {@link ShadowAlgorithm#NONE}) is disabled and costs nothing.
 *
 * @param tint             the colour ramp, or {@code null} for a plain mid-gray base (0.5, the original's gray tint)
 * @param hillshade        the hillshade method, or {@code null} for none (illumination 0 everywhere)
 * @param hillshadeOptions z-factor, light multiple and the tone (light/dark intensity, spot exponent)
 * @param shadows          the cast-shadow algorithm, or {@code null}/NONE for none
 * @param shadowOptions    options of the cast-shadow algorithm
 * @param light            the light (uniform, or varying over the grid)
 * @param shadowIntensity  a cell in cast shadow loses 2 × this much brightness (original 0.4)
 * @param fade             extra darkening in [0, 2] for the whole scene, e.g. the twilight fade (0 in daylight)
 * @param tintRange        the elevation range a percent tint is stretched over, or {@code null} for the rendered
 *                         DEM's own range (give the whole file's range when rendering a window or a reduced copy)
 * @param lightModel       how sun, cast shadows and sky combine ({@link LightModel}; the original's: JDEM846)
 * @param ambient          the weight W of the light of the sky, 0 to 1; above 0 the sky-view factor of every cell
 *                         is computed ({@link SkyView}), at 0 it is not
 * @param skyDirections    the number of azimuths of the sky-view factor ({@link SkyViewOptions#directions()})
 * @param skyRadius        the sky-view factor's search radius in ground metres ({@link SkyViewOptions#radius()});
 *                         {@link SkyViewOptions#UNBOUNDED} for none
 * @param blend            how the shading is laid on the tint ({@link Blend}; the original's: eq. 8, opaque)
 * @param drape            colours laid over the tint before the light (a draped image, {@link
 *                         io.github.jdem846.drape.Drape}), or {@code null} for the tint alone
 */
public record Scene(ColorRamp tint, HillshadeMethod hillshade, HillshadeOptions hillshadeOptions,
                    ShadowAlgorithm shadows, ShadowOptions shadowOptions, LightField light,
                    double shadowIntensity, double fade, ElevationStatistics tintRange, LightModel lightModel,
                    double ambient, int skyDirections, double skyRadius, Blend blend, ColorLayer drape) {

    /**
     * Checks that the options and light are given and that the weights are in range.
     *
     * @param tint the colour ramp, or {@code null} for a plain mid-gray base (0.5, the original's gray tint)
     * @param hillshade the hillshade method, or {@code null} for none (illumination 0 everywhere)
     * @param hillshadeOptions z-factor, light multiple and the tone (light/dark intensity, spot exponent)
     * @param shadows the cast-shadow algorithm, or {@code null}/NONE for none
     * @param shadowOptions options of the cast-shadow algorithm
     * @param light the light (uniform, or varying over the grid)
     * @param shadowIntensity a cell in cast shadow loses 2 × this much brightness (original 0.4)
     * @param fade extra darkening in [0, 2] for the whole scene, e.g. the twilight fade (0 in daylight)
     * @param tintRange the elevation range a percent tint is stretched over, or {@code null} for the rendered DEM's own
     *     range (give the whole file's range when rendering a window or a reduced copy)
     * @param lightModel how sun, cast shadows and sky combine ({@link LightModel}; the original's: JDEM846)
     * @param ambient the weight W of the light of the sky, 0 to 1; above 0 the sky-view factor of every cell is
     *     computed ({@link SkyView}), at 0 it is not
     * @param skyDirections the number of azimuths of the sky-view factor ({@link SkyViewOptions#directions()})
     * @param skyRadius the sky-view factor's search radius in ground metres ({@link SkyViewOptions#radius()});
     *     {@link SkyViewOptions#UNBOUNDED} for none
     * @param blend how the shading is laid on the tint ({@link Blend}; the original's: eq. 8, opaque)
     * @param drape colours laid over the tint before the light (a draped image), or {@code null} for the tint alone
     */
    public Scene {
        Objects.requireNonNull(hillshadeOptions, "hillshadeOptions");
        Objects.requireNonNull(shadowOptions, "shadowOptions");
        Objects.requireNonNull(light, "light");
        if (!(shadowIntensity >= 0 && shadowIntensity <= 1)) {
            throw new IllegalArgumentException("shadow intensity must be between 0 and 1 (default 0.4), got "
                    + shadowIntensity);
        }
        if (!(fade >= 0 && fade <= 2)) {
            throw new IllegalArgumentException("fade must be between 0 and 2, got " + fade);
        }
        Objects.requireNonNull(lightModel, "lightModel");
        if (!(ambient >= 0 && ambient <= 1)) {
            throw new IllegalArgumentException("ambient (sky light) weight must be between 0 and 1, got " + ambient);
        }
        new SkyViewOptions(skyDirections, 1, skyRadius);      // validates the number of directions and the radius
        Objects.requireNonNull(blend, "blend");
    }

    /**
     * The original's defaults: the article's hypsometric tint (table 2; on a DEM holding land and sea, table 2 above
     * 0 m and the original's bathymetric ramp below, {@link ColorRamp#defaultRamp()}), jDem846 hillshade with light
     * multiple 0.75 and intensities 0.75/1.0, no cast shadows, sun at azimuth 320° and elevation 25°, shadow
     * intensity 0.4, the original's light model without sky light ({@link LightModel#JDEM846}, ambient 0), eq. 8
     * fully opaque ({@link Blend#DEFAULT}).
     *
     * @return the default scene
     */
    public static Scene defaults() {
        return new Scene(ColorRamp.defaultRamp(), HillshadeMethod.JDEM846, HillshadeOptions.DEFAULTS,
                ShadowAlgorithm.NONE, ShadowOptions.DEFAULTS, LightField.uniform(LightDirection.ORIGINAL_DEFAULT),
                Compositor.DEFAULT_SHADOW_INTENSITY, 0, null, LightModel.JDEM846, 0, SkyViewOptions.DEFAULT_DIRECTIONS,
                SkyViewOptions.UNBOUNDED, Blend.DEFAULT, null);
    }

    /**
     * The same scene with another tint.
     *
     * @param ramp the tint ramp, or {@code null} for plain gray
     * @return the new scene
     */
    public Scene withTint(ColorRamp ramp) {
        return new Scene(ramp, hillshade, hillshadeOptions, shadows, shadowOptions, light, shadowIntensity, fade, tintRange, lightModel, ambient, skyDirections, skyRadius, blend, drape);
    }

    /**
     * The same scene with another hillshade method.
     *
     * @param method the method, or {@code null} for none
     * @return the new scene
     */
    public Scene withHillshade(HillshadeMethod method) {
        return new Scene(tint, method, hillshadeOptions, shadows, shadowOptions, light, shadowIntensity, fade, tintRange, lightModel, ambient, skyDirections, skyRadius, blend, drape);
    }

    /**
     * The same scene with other hillshade options.
     *
     * @param options z-factor, intensities and spot exponent
     * @return the new scene
     */
    public Scene withHillshadeOptions(HillshadeOptions options) {
        return new Scene(tint, hillshade, options, shadows, shadowOptions, light, shadowIntensity, fade, tintRange, lightModel, ambient, skyDirections, skyRadius, blend, drape);
    }

    /**
     * The same scene with another cast-shadow algorithm.
     *
     * @param algorithm the algorithm, or {@code null} or NONE for none
     * @return the new scene
     */
    public Scene withShadows(ShadowAlgorithm algorithm) {
        return new Scene(tint, hillshade, hillshadeOptions, algorithm, shadowOptions, light, shadowIntensity, fade, tintRange, lightModel, ambient, skyDirections, skyRadius, blend, drape);
    }

    /**
     * The same scene with other cast-shadow options.
     *
     * @param options the cast-shadow settings
     * @return the new scene
     */
    public Scene withShadowOptions(ShadowOptions options) {
        return new Scene(tint, hillshade, hillshadeOptions, shadows, options, light, shadowIntensity, fade, tintRange, lightModel, ambient, skyDirections, skyRadius, blend, drape);
    }

    /**
     * The same scene under one light direction.
     *
     * @param direction where the light comes from
     * @return the new scene
     */
    public Scene withLight(LightDirection direction) {
        return withLight(LightField.uniform(direction));
    }

    /**
     * The same scene under a light that may vary over the grid.
     *
     * @param field the light, uniform or varying over the grid
     * @return the new scene
     */
    public Scene withLight(LightField field) {
        return new Scene(tint, hillshade, hillshadeOptions, shadows, shadowOptions, field, shadowIntensity, fade, tintRange, lightModel, ambient, skyDirections, skyRadius, blend, drape);
    }

    /**
     * The same scene with another shadow intensity.
     *
     * @param intensity how dark a cast shadow is, 0 to 1
     * @return the new scene
     */
    public Scene withShadowIntensity(double intensity) {
        return new Scene(tint, hillshade, hillshadeOptions, shadows, shadowOptions, light, intensity, fade, tintRange, lightModel, ambient, skyDirections, skyRadius, blend, drape);
    }

    /**
     * The same scene with a global darkening (twilight fade).
     *
     * @param darkening the global darkening, 0 to 2
     * @return the new scene
     */
    public Scene withFade(double darkening) {
        return new Scene(tint, hillshade, hillshadeOptions, shadows, shadowOptions, light, shadowIntensity,
                darkening, tintRange, lightModel, ambient, skyDirections, skyRadius, blend, drape);
    }

    /**
     * The same scene with a fixed range for percent tints.
     *
     * @param range the range, or {@code null} for the rendered DEM's own range
     * @return the new scene
     */
    public Scene withTintRange(ElevationStatistics range) {
        return new Scene(tint, hillshade, hillshadeOptions, shadows, shadowOptions, light, shadowIntensity, fade,
                range, lightModel, ambient, skyDirections, skyRadius, blend, drape);
    }

    /**
     * The same scene with another light model.
     *
     * @param model how sun, cast shadows and sky combine
     * @return the new scene
     */
    public Scene withLightModel(LightModel model) {
        return new Scene(tint, hillshade, hillshadeOptions, shadows, shadowOptions, light, shadowIntensity, fade,
                tintRange, model, ambient, skyDirections, skyRadius, blend, drape);
    }

    /**
     * The same scene with another weight of the light of the sky.
     *
     * @param weight 0 (no sky light, no sky-view factor computed) to 1
     * @return the new scene
     */
    public Scene withAmbient(double weight) {
        return new Scene(tint, hillshade, hillshadeOptions, shadows, shadowOptions, light, shadowIntensity, fade,
                tintRange, lightModel, weight, skyDirections, skyRadius, blend, drape);
    }

    /**
     * The same scene with another number of sky-view azimuths.
     *
     * @param directions 4 to 360 ({@link SkyViewOptions})
     * @return the new scene
     */
    public Scene withSkyDirections(int directions) {
        return new Scene(tint, hillshade, hillshadeOptions, shadows, shadowOptions, light, shadowIntensity, fade,
                tintRange, lightModel, ambient, directions, skyRadius, blend, drape);
    }

    /**
     * The same scene with another search radius of the sky-view factor.
     *
     * @param metres the radius in ground metres, positive; {@link SkyViewOptions#UNBOUNDED} for none
     * @return the new scene
     */
    public Scene withSkyRadius(double metres) {
        return new Scene(tint, hillshade, hillshadeOptions, shadows, shadowOptions, light, shadowIntensity, fade,
                tintRange, lightModel, ambient, skyDirections, metres, blend, drape);
    }

    /**
     * The same scene with another way of laying the shading on the tint.
     *
     * @param b the blend mode and opacity ({@link Blend#DEFAULT}: eq. 8, opaque)
     * @return the new scene
     */
    public Scene withBlend(Blend b) {
        return new Scene(tint, hillshade, hillshadeOptions, shadows, shadowOptions, light, shadowIntensity, fade,
                tintRange, lightModel, ambient, skyDirections, skyRadius, b, drape);
    }

    /**
     * The same scene with colours laid over the tint, cell by cell, before the light: a draped image ({@link
     * io.github.jdem846.drape.Drape}); where the layer is transparent the tint shows.
     *
     * @param layer the colours, or {@code null} for the tint alone
     * @return the new scene
     */
    public Scene withDrape(ColorLayer layer) {
        return new Scene(tint, hillshade, hillshadeOptions, shadows, shadowOptions, light, shadowIntensity, fade,
                tintRange, lightModel, ambient, skyDirections, skyRadius, blend, layer);
    }

    /** {@return true when the sky-view factor is to be computed (an ambient weight above 0)} */
    public boolean hasAmbient() {
        return ambient > 0;
    }

    /**
     * The settings of the sky-view stage: the scene's directions and search radius, heights exaggerated by the z-factor as the
     * hillshade shows them.
     *
     * @return the sky-view options
     */
    public SkyViewOptions skyViewOptions() {
        return new SkyViewOptions(skyDirections, hillshadeOptions.zFactor(), skyRadius);
    }

    /**
     * The light the cast shadows are traced with: the central light, for terrain exaggerated by the z-factor (the
     * shadows of the terrain the hillshade shows; {@link LightDirection#forHeightsScaledBy(double)}).
     *
     * @return the light for the shadow stage
     */
    public LightDirection shadowLight() {
        return light.central().forHeightsScaledBy(hillshadeOptions.zFactor());
    }

    /** {@return true when cast shadows are to be computed} */
    public boolean hasShadows() {
        return shadows != null && shadows != ShadowAlgorithm.NONE;
    }
}
