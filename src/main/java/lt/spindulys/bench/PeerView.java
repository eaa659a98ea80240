package lt.spindulys.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.AreaLight;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.SceneBuilder;

/**
 * One bench view as the peer renderers are told it: a pinhole camera, one point light with
 * inverse-square falloff, the image size and the OBJ meshes (grey Lambert 0.8, flat normals,
 * 1 sample per pixel, direct light only, as every bench scene of the peer kind). It is read from
 * our own scene file, so the peers render what we render.
 *
 * @param eye              the camera's position
 * @param at               the point it looks at
 * @param up               its up direction
 * @param verticalFov      vertical field of view, degrees
 * @param width            image width, pixels
 * @param height           image height, pixels
 * @param light            the point light's position
 * @param radiantIntensity the light's radiant intensity, W/sr (with the 1/pi of a Lambert BRDF)
 * @param meshes           the OBJ files, in the scene's order
 * @param area             for a soft-shadow view, the area light whose centre is {@code light};
 *                         null for a point light
 */
record PeerView(Vec3 eye, Vec3 at, Vec3 up, double verticalFov, int width, int height, Vec3 light, double radiantIntensity,
                List<Path> meshes, Area area) {
    /** A point-light view. */
    PeerView(Vec3 eye, Vec3 at, Vec3 up, double verticalFov, int width, int height, Vec3 light, double radiantIntensity, List<Path> meshes) {
        this(eye, at, up, verticalFov, width, height, light, radiantIntensity, meshes, null);
    }

    /**
     * A rectangle or disc light as POV-Ray's {@code area_light} is told it: its two full edge
     * vectors (a disc's two diameters, with {@code circular}) and a {@code grid} x {@code grid}
     * array of jittered samples.
     */
    record Area(boolean disc, Vec3 axis1, Vec3 axis2, int grid) {}

    /**
     * The view of {@code scene}, whose meshes are {@code meshes}. Our Whitted diffuse term is
     * kd * colour * cos, without the 1/pi of a Lambert BRDF, so the scene's intensity is the
     * radiant intensity divided by pi (scenes/bench/torus-1m.dat).
     *
     * @throws IOException if the scene is not of the kind the peers are given (one white
     *         inverse-square point light, a pinhole camera)
     */
    static PeerView of(SceneBuilder scene, List<Path> meshes) throws IOException {
        if (!(scene.camera() instanceof PinholeCamera cam)) throw new IOException("a peer view needs a pinhole camera");
        if (scene.lights().size() != 1) throw new IOException("a peer view needs exactly one light, found " + scene.lights().size());
        PointLight l = scene.lights().get(0);
        if (l.falloff() != PointLight.Falloff.INVERSE_SQUARE || l.color().r() != 1 || l.color().g() != 1 || l.color().b() != 1) {
            throw new IOException("a peer view needs a white light with inverse-square falloff");
        }
        return new PeerView(cam.eye(), cam.lookAt(), cam.up(), cam.fovDegrees(), scene.settings().width(), scene.settings().height(),
                l.position(), l.intensity() * Math.PI, List.copyOf(meshes));
    }

    /**
     * The view of a path-traced {@code scene} (one white inverse-square point light, a pinhole
     * camera): its Lambert BRDF has the 1/pi, so the light's intensity is its radiant intensity.
     *
     * @throws IOException if the scene is not of that kind
     */
    static PeerView ofPath(SceneBuilder scene, List<Path> meshes) throws IOException {
        PeerView v = of(scene, meshes);
        return new PeerView(v.eye, v.at, v.up, v.verticalFov, v.width, v.height, v.light, v.radiantIntensity / Math.PI, v.meshes, null);
    }

    /** This view at another image size. */
    PeerView withSize(int w, int h) {
        return new PeerView(eye, at, up, verticalFov, w, h, light, radiantIntensity, meshes, area);
    }

    /**
     * The soft-shadow view of {@code scene}: one white rectangle or disc light, no point light, a
     * pinhole camera. Each pixel's shadow rays (pixel samples x light samples) become a grid x
     * grid area_light, so their number must be a square. The radiant intensity is
     * the light's straight below it, radiance x area x pi (its light-side cosine is then 1), so
     * that the point light's conversion in {@link PeerInputs#povScene} carries over.
     *
     * @throws IOException if the scene is not of that kind
     */
    static PeerView ofArea(SceneBuilder scene, List<Path> meshes) throws IOException {
        if (!(scene.camera() instanceof PinholeCamera cam)) throw new IOException("a peer view needs a pinhole camera");
        if (!scene.lights().isEmpty() || scene.areaLights().size() != 1) {
            throw new IOException("a soft-shadow peer view needs exactly one area light and no point light");
        }
        AreaLight l = scene.areaLights().get(0);
        if (l.shape() == AreaLight.Shape.SPHERE || l.color().r() != 1 || l.color().g() != 1 || l.color().b() != 1) {
            throw new IOException("a soft-shadow peer view needs a white rectangle or disc light");
        }
        int rays = scene.settings().samplesPerPixel() * l.samples(), grid = (int) Math.round(Math.sqrt(rays));
        if (grid * grid != rays) throw new IOException("a soft-shadow peer view needs a square number of shadow rays per pixel, found " + rays);
        return new PeerView(cam.eye(), cam.lookAt(), cam.up(), cam.fovDegrees(), scene.settings().width(), scene.settings().height(),
                l.center(), l.intensity() * l.area() * Math.PI, List.copyOf(meshes),
                new Area(l.shape() == AreaLight.Shape.DISC, l.halfU().times(2), l.halfV().times(2), grid));
    }

    /** {@return the horizontal field of view in degrees, for the renderers that take that one} */
    double horizontalFov() {
        return Math.toDegrees(2 * Math.atan(Math.tan(Math.toRadians(verticalFov / 2)) * width / height));
    }
}
